#pragma once
// Who evaluates a human's vertices: the renderer's vertex shader from the patches' control
// points, or the CPU, as the user asked (the display's "Vertex Evaluation") and as the renderer
// allows. Automatic picks the vertex shader on a GPU and the CPU on a software renderer, whose
// vertex shader runs on one thread of the viewer (bench/rviz_scaling.py measures both).

#include <cstddef>
#include <string>

#include "dressed_human/core/model/human_model.h"

namespace dressed_human {

enum class VertexEvaluationRequest { kAutomatic, kGpu, kCpu };  // what the user asked

struct VertexEvaluationChoice {
  VertexEvaluation evaluation = VertexEvaluation::kCpu;
  bool warn = false;   // the user's choice could not be followed
  std::string status;  // what to tell the user; empty: nothing
};

// `renderer_problem`: why the renderer's vertex shader cannot run (empty: it can).
// `software_renderer`: the renderer's name when it rasterizes on the CPU, empty on a GPU.
// `max_patches`: the most patches of one part the vertex shader holds.
VertexEvaluationChoice chooseVertexEvaluation(VertexEvaluationRequest asked, const HumanModel& model,
                                              const std::string& renderer_problem, const std::string& software_renderer,
                                              std::size_t max_patches);

}  // namespace dressed_human
