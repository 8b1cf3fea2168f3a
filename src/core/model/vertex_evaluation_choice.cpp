#include "dressed_human/core/model/vertex_evaluation_choice.h"

namespace dressed_human {

VertexEvaluationChoice chooseVertexEvaluation(VertexEvaluationRequest asked, const HumanModel& model,
                                              const std::string& renderer_problem, const std::string& software_renderer,
                                              std::size_t max_patches) {
  VertexEvaluationChoice choice;
  if (asked == VertexEvaluationRequest::kAutomatic && !software_renderer.empty()) {
    choice.status = "CPU (Automatic): " + software_renderer +
                    " renders in software, its vertex shader would run on one thread of rviz";
    return choice;
  }
  if (asked == VertexEvaluationRequest::kCpu) return choice;
  std::string problem = renderer_problem;
  for (std::size_t p = 0; problem.empty() && p < model.parts().size(); ++p) {
    if (model.partPatches(p).size() > max_patches) {
      problem = model.parts()[p].name + " has " + std::to_string(model.partPatches(p).size()) +
                " patches, the vertex shader holds " + std::to_string(max_patches);
    }
  }
  if (!problem.empty()) {
    choice.warn = true;
    choice.status = problem + "; the CPU evaluates the vertices";
    return choice;
  }
  choice.evaluation = VertexEvaluation::kGpu;
  return choice;
}

}  // namespace dressed_human
