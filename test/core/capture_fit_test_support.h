#pragma once
// A CMU capture retargeted (on its fitted body or on ours) with our drawn feet, as fit_motion does,
// fitted with the default options and measured against the capture; and two such fits compared on
// our skeleton's floor.

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/fit_accuracy.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion_fit.h"

namespace dressed_human {

struct FittedCapture {
  SampledMotion sampled;
  FitAccuracy accuracy;
};

inline FittedCapture fitCmuCapture(const Skeleton& skeleton, const BvhClip& clip, const std::string& path,
                                   bool fit_body) {
  RetargetOptions options;
  options.fit_body = fit_body;
  options.body = std::make_shared<const BodyDescription>(
      loadBodyDescriptionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/bodies/default.yaml", skeleton));
  FittedCapture fitted;
  fitted.sampled = retargetBvh(clip, chooseBvhJointMap(clip, path), skeleton, path, options);
  if (fit_body) {
    EXPECT_EQ(fitted.sampled.units.name, "cmu") << path << ": " << fitted.sampled.units.reason;
  }
  const MotionFit fit = fitMotion(fitted.sampled, MotionFitOptions());
  fitted.accuracy = measureFitAccuracy(skeleton, fitted.sampled, fit, fit.motion);
  return fitted;
}

// Our skeleton on the unsmoothed retarget of `changed` (a variant of the `reference` capture)
// within `max_slack` (worst frame) and `mean_slack` cm of the reference's; both printed.
inline void expectUnsmoothedAsClose(const FitAccuracy& reference, const FitAccuracy& changed, const char* change,
                                    double max_slack, double mean_slack) {
  const PositionError& a = reference.unsmoothed_against_capture;
  const PositionError& b = changed.unsmoothed_against_capture;
  std::printf("unsmoothed retarget: as captured %.2f / %.2f cm, %s %.2f / %.2f cm\n", a.mean_cm, a.max_cm, change,
              b.mean_cm, b.max_cm);
  EXPECT_LE(b.max_cm, a.max_cm + max_slack) << change;
  EXPECT_LE(b.mean_cm, a.mean_cm + mean_slack) << change;
}

}  // namespace dressed_human
