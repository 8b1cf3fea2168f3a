// Who evaluates the vertices (vertex_evaluation_choice.h): the user's choice where the renderer
// allows it, the CPU with a warning naming why where it does not, and Automatic's pick by renderer.
#include "dressed_human/core/model/vertex_evaluation_choice.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "garment_test_support.h"

namespace dressed_human {
namespace {

using namespace garment_test;

HumanModel dressedModel() {
  HumanModelSettings settings;
  settings.outfit = Outfit::kJacketSkirt;
  settings.garment_directory = sourcePath("config/garments");
  return HumanModel(skeleton(), body(), settings);
}

std::size_t mostPatches(const HumanModel& model) {
  std::size_t most = 0;
  for (std::size_t p = 0; p < model.parts().size(); ++p) most = std::max(most, model.partPatches(p).size());
  return most;
}

TEST(VertexEvaluationChoice, AutomaticPicksTheRendererOnAGpuAndTheCpuOnASoftwareRenderer) {
  const HumanModel model = dressedModel();
  const std::size_t room = mostPatches(model);
  const VertexEvaluationChoice gpu = chooseVertexEvaluation(VertexEvaluationRequest::kAutomatic, model, "", "", room);
  EXPECT_EQ(gpu.evaluation, VertexEvaluation::kGpu);
  EXPECT_FALSE(gpu.warn);
  EXPECT_TRUE(gpu.status.empty());
  const VertexEvaluationChoice software =
      chooseVertexEvaluation(VertexEvaluationRequest::kAutomatic, model, "", "llvmpipe", room);
  EXPECT_EQ(software.evaluation, VertexEvaluation::kCpu);
  EXPECT_FALSE(software.warn);
  EXPECT_NE(software.status.find("llvmpipe"), std::string::npos) << software.status;
}

TEST(VertexEvaluationChoice, TheUsersChoiceHoldsWhereTheRendererAllowsIt) {
  const HumanModel model = dressedModel();
  const std::size_t room = mostPatches(model);
  EXPECT_EQ(chooseVertexEvaluation(VertexEvaluationRequest::kGpu, model, "", "llvmpipe", room).evaluation,
            VertexEvaluation::kGpu);
  const VertexEvaluationChoice cpu = chooseVertexEvaluation(VertexEvaluationRequest::kCpu, model, "", "", room);
  EXPECT_EQ(cpu.evaluation, VertexEvaluation::kCpu);
  EXPECT_TRUE(cpu.status.empty());
}

TEST(VertexEvaluationChoice, WhatTheRendererCannotDoFallsBackToTheCpuWithItsReason) {
  const HumanModel model = dressedModel();
  const std::size_t room = mostPatches(model);
  const VertexEvaluationChoice no_shader =
      chooseVertexEvaluation(VertexEvaluationRequest::kGpu, model, "the relief material did not load", "", room);
  EXPECT_EQ(no_shader.evaluation, VertexEvaluation::kCpu);
  EXPECT_TRUE(no_shader.warn);
  EXPECT_NE(no_shader.status.find("the relief material did not load"), std::string::npos) << no_shader.status;
  const VertexEvaluationChoice too_many =
      chooseVertexEvaluation(VertexEvaluationRequest::kAutomatic, model, "", "", room - 1);
  EXPECT_EQ(too_many.evaluation, VertexEvaluation::kCpu);
  EXPECT_TRUE(too_many.warn);
  EXPECT_NE(too_many.status.find(std::to_string(room) + " patches"), std::string::npos) << too_many.status;
}

}  // namespace
}  // namespace dressed_human
