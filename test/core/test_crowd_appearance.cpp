#include "dressed_human/core/model/crowd_appearance.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "temp_file_path.h"

namespace dressed_human {
namespace {

std::string writeCrowdFile(const std::string& name, const std::string& text) {
  const std::string path = tempFilePath(name);
  std::ofstream(path) << text;
  return path;
}

std::string crowdFileError(const std::string& text) {
  const std::string path = writeCrowdFile("crowd_error.yaml", text);
  try {
    loadCrowdFile(path);
  } catch (const CrowdFileError& error) {
    std::remove(path.c_str());
    return error.what();
  }
  std::remove(path.c_str());
  return "(no error)";
}

TEST(CrowdAppearance, TheShippedExampleSetsWhatItNames) {
  const auto crowd = loadCrowdFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/crowds/example.yaml");
  ASSERT_EQ(crowd.size(), 3u);
  HumanModelSettings settings;
  crowd.at("1").applyTo(settings);
  EXPECT_EQ(settings.outfit, Outfit::kOnePiece);
  EXPECT_TRUE(settings.skin_colour.isApprox(Eigen::Vector4f(0.48f, 0.33f, 0.23f, 1.0f)));
  EXPECT_TRUE(settings.garment_colours.at("one_piece").isApprox(Eigen::Vector4f(0.72f, 0.22f, 0.30f, 1.0f)));
  EXPECT_EQ(settings.garment_colours.count("pants"), 0u);  // no lower colour given: the file's stays
  HumanModelSettings untouched;
  crowd.at("2").applyTo(untouched);
  EXPECT_EQ(untouched.outfit, Outfit::kJacketSkirt);
  EXPECT_TRUE(untouched.garment_colours.empty());
  EXPECT_TRUE(untouched.skin_colour.isApprox(HumanModelSettings().skin_colour));
}

TEST(CrowdAppearance, VariedByIdTheSameEveryTimeAndDifferentAcrossACrowd) {
  std::set<int> outfits;
  std::set<std::string> looks;
  for (int id = 0; id < 30; ++id) {
    const HumanAppearance a = variedAppearance(std::to_string(id));
    const HumanAppearance again = variedAppearance(std::to_string(id));
    ASSERT_TRUE(a.outfit && a.skin_colour && a.upper_colour && a.lower_colour);
    EXPECT_EQ(*a.outfit, *again.outfit);
    EXPECT_TRUE(a.upper_colour->isApprox(*again.upper_colour));
    EXPECT_FALSE(a.upper_colour->isApprox(*a.lower_colour)) << "human " << id << " in one colour";
    outfits.insert(static_cast<int>(*a.outfit));
    looks.insert(std::to_string(static_cast<int>(*a.outfit)) + std::to_string(a.upper_colour->x()) +
                 std::to_string(a.lower_colour->x()) + std::to_string(a.skin_colour->x()));
  }
  EXPECT_EQ(outfits.size(), 3u);
  EXPECT_GE(looks.size(), 25u);  // 180 outfit and colour combinations for 30 humans
}

TEST(CrowdAppearance, BadFilesNameFileLineAndKey) {
  EXPECT_NE(crowdFileError("people: {}\n").find("crowd_error.yaml"), std::string::npos);
  EXPECT_NE(crowdFileError("people: {}\n").find("people"), std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"3\": {outfit: kilt}\n").find(":2:"), std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"3\": {outfit: kilt}\n").find("humans.3.outfit: unknown outfit 'kilt'"),
            std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"3\": {skin_colour: [1, 2, 0]}\n")
                .find("humans.3.skin_colour[1]: must lie in [0, 1]"),
            std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"3\": {hat: red}\n").find("hat"), std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"a-b\": {}\n").find("letters and digits"), std::string::npos);
  EXPECT_NE(crowdFileError("humans:\n  \"3\": {}\n  \"3\": {}\n").find("twice"), std::string::npos);
  EXPECT_NE(crowdFileError("humans: [1, 2]\n").find("expected a mapping"), std::string::npos);
  try {
    loadCrowdFile("/nonexistent/crowd.yaml");
    FAIL() << "no error for a missing file";
  } catch (const CrowdFileError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/crowd.yaml: cannot open the crowd file"), std::string::npos);
  }
}

}  // namespace
}  // namespace dressed_human
