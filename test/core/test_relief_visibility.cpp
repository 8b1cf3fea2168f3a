// ReliefVisibility (model/relief_visibility.h): a relief is drawn while its features cover at
// least two pixels, switched off and on again with hysteresis as a human walks away and back,
// and the feature sizes the display derives from the model are those of its patches.
#include "dressed_human/core/model/relief_visibility.h"

#include <gtest/gtest.h>

#include "dressed_human/core/model/human_model.h"
#include "garment_test_support.h"

namespace dressed_human {
namespace {

BezierPatch flatSquare(double side) {
  BezierPatch::ControlPoints points;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i)
      points[static_cast<std::size_t>(4 * j + i)] = Eigen::Vector3d(side * i / 3.0, side * j / 3.0, 0.0);
  }
  return BezierPatch(points);
}

TEST(ReliefVisibility, TypicalPatchSizeIsTheMedianLargerSide) {
  EXPECT_NEAR(typicalPatchSize({flatSquare(0.1)}), 0.1, 1e-12);
  EXPECT_NEAR(typicalPatchSize({flatSquare(0.1), flatSquare(0.3), flatSquare(0.2)}), 0.2, 1e-12);
  EXPECT_THROW(typicalPatchSize({}), std::invalid_argument);
}

TEST(ReliefVisibility, HidesWhereItWouldFadeToNothingAndShowsAgainWithHysteresis) {
  const CameraView camera{Eigen::Vector3d::Zero(), 0.8, 700.0};
  ReliefVisibility visibility(0.01);                                                       // 1 cm features
  const double hide = 0.01 * pixelsPerMetre(camera, 1.0) / ReliefVisibility::kHidePixels;  // metres
  EXPECT_NEAR(0.01 * pixelsPerMetre(camera, hide), ReliefVisibility::kHidePixels, 1e-9);
  // Walking away: shown until just beyond the hide distance.
  EXPECT_TRUE(visibility.update(pixelsPerMetre(camera, 0.99 * hide)));
  EXPECT_FALSE(visibility.update(pixelsPerMetre(camera, 1.01 * hide)));
  // Walking back: still hidden inside the hysteresis band, shown once the features are kShowPixels.
  EXPECT_FALSE(visibility.update(pixelsPerMetre(camera, 0.98 * hide)));
  const double show = hide * ReliefVisibility::kHidePixels / ReliefVisibility::kShowPixels;
  EXPECT_FALSE(visibility.update(pixelsPerMetre(camera, 1.01 * show)));
  EXPECT_TRUE(visibility.update(pixelsPerMetre(camera, 0.99 * show)));
  // Jitter around the hide distance (a walking human's nearest point moves by about 1 % at
  // 12 m) does not toggle.
  int toggles = 0;
  bool last = visibility.update(pixelsPerMetre(camera, hide * 1.015));
  for (int i = 0; i < 100; ++i) {
    const bool now = visibility.update(pixelsPerMetre(camera, hide * (i % 2 == 0 ? 0.985 : 1.015)));
    toggles += now != last ? 1 : 0;
    last = now;
  }
  EXPECT_EQ(toggles, 0);
  EXPECT_THROW(ReliefVisibility(0.0), std::invalid_argument);
  EXPECT_THROW(ReliefVisibility(std::nan("")), std::invalid_argument);
}

TEST(ReliefVisibility, TheModelsFeatureSizes) {
  using namespace garment_test;
  HumanModelSettings settings;
  settings.outfit = Outfit::kJacketSkirt;
  settings.garment_directory = sourcePath("config/garments");
  HumanModel model(skeleton(), body(), settings);
  // Skin: its largest cells, a millimetre or so on the body (skin_relief_tiling.h), whatever
  // the patches' size.
  const double skin = model.reliefFeatureSize(ReliefKind::kSkin);
  EXPECT_GT(skin, 0.8e-3);
  EXPECT_LT(skin, 2e-3);
  model.setSkinCellSize(2.0 * SkinReliefTiling::measuredForearmSpacing());
  EXPECT_NEAR(model.reliefFeatureSize(ReliefKind::kSkin), 2.0 * skin, 1e-12);
  EXPECT_THROW(model.setSkinCellSize(0.0), std::invalid_argument);
  // Cloth: folds half a buckling cell apart, 2 cells per fold tile and 3 tiles per patch: a few
  // centimetres on the garments' large patches.
  const double cloth = model.reliefFeatureSize(ReliefKind::kCloth);
  EXPECT_GT(cloth, 0.005);
  EXPECT_LT(cloth, 0.07);
  settings.outfit = Outfit::kNone;
  EXPECT_EQ(HumanModel(skeleton(), body(), settings).reliefFeatureSize(ReliefKind::kCloth), 0.0);
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

// The relief fades in and out instead of popping: flat (0) wherever the switch has it off and
// where it turns off, full from kFullPixels, continuous and monotone between (steps under 0.01,
// the switching on included), whichever way the camera moves.
TEST(ReliefVisibility, FadesToNothingWhereItIsSwitched) {
  ReliefVisibility visibility(0.01);  // features 1 cm apart: pixels = pixels_per_metre / 100
  EXPECT_EQ(visibility.fade(), 1.0);
  double previous = 0.0;                     // from 0 px
  for (int step = 0; step <= 800; ++step) {  // approaching: 0 to 8 px
    const double pixels = step * 0.01;
    const bool shown = visibility.update(pixels * 100.0);
    if (!shown || pixels <= ReliefVisibility::kHidePixels) {
      EXPECT_EQ(visibility.fade(), 0.0) << pixels;
    }
    if (pixels <= ReliefVisibility::kShowPixels) {
      EXPECT_FALSE(shown) << pixels;
    }
    if (pixels >= ReliefVisibility::kFullPixels) {
      EXPECT_EQ(visibility.fade(), 1.0) << pixels;
    }
    EXPECT_GE(visibility.fade(), previous);
    EXPECT_LT(visibility.fade() - previous, 0.01) << "a jump at " << pixels << " px";
    previous = visibility.fade();
  }
  for (int step = 800; step >= 0; --step) {  // leaving
    const double pixels = step * 0.01;
    const bool shown = visibility.update(pixels * 100.0);
    if (!shown) {
      EXPECT_EQ(visibility.fade(), 0.0) << pixels;
    }
    EXPECT_LE(visibility.fade(), previous);
    EXPECT_LT(previous - visibility.fade(), 0.01) << "a jump at " << pixels << " px";
    previous = visibility.fade();
  }
}

}  // namespace
}  // namespace dressed_human
