// Body description YAML (config/bodies/*.yaml): the default loads; bad files fail with errors
// that name file:line:col and the key path.
#include "dressed_human/core/skeleton/body_description.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;

const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  return s;
}

std::string defaultText() {
  std::ifstream file(kSource + "/config/bodies/default.yaml");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Parses, expects a BodyDescriptionError whose message contains every fragment.
void expectError(const std::string& text, std::initializer_list<std::string> fragments) {
  try {
    parseBodyDescriptionYaml(text, skeleton(), "bad.yaml");
    ADD_FAILURE() << "no error for fragments starting with " << *fragments.begin();
  } catch (const BodyDescriptionError& error) {
    const std::string message = error.what();
    for (const std::string& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
    }
  }
}

TEST(BodyDescription, DefaultAdultLoads) {
  const BodyDescription body = loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton());
  EXPECT_EQ(body.name, "default adult");
  EXPECT_EQ(body.segments.size(), 19u);  // 20 bones minus the 2 hip bones, plus the pelvis region
  EXPECT_EQ(body.segments.front().bone, "body");
  for (const SkinSegmentSpec& segment : body.segments) {
    EXPECT_GE(segment.sections.size(), 1u) << segment.bone;
    if (segment.bone != "body") {
      EXPECT_EQ(skeleton().bone(static_cast<std::size_t>(segment.bone_index)).name, segment.bone);
    }
  }
  for (const Eigen::Vector3d& scale : body.shape.scale) EXPECT_EQ(scale, Eigen::Vector3d::Ones());
}

TEST(BodyDescription, ShapeGroupsAndBones) {
  const std::string text = replaced(defaultText(), "all: [1.0, 1.0, 1.0]",
                                    "legs: [1.1, 1.2, 1.3]\n  l_knee: [0.9, 0.9, 1.0]\n  head_neck: [1, 1, 1.1]");
  const BodyDescription body = parseBodyDescriptionYaml(text, skeleton());
  auto scale = [&](const char* bone) { return body.shape.scale[static_cast<std::size_t>(skeleton().findBone(bone))]; };
  EXPECT_EQ(scale("r_hip"), Eigen::Vector3d(1.1, 1.2, 1.3));
  EXPECT_EQ(scale("l_knee"), Eigen::Vector3d(0.9, 0.9, 1.0));  // later entries override
  EXPECT_EQ(scale("head"), Eigen::Vector3d(1.0, 1.0, 1.1));
  EXPECT_EQ(scale("torso"), Eigen::Vector3d::Ones());
}

TEST(BodyDescription, BadFiles) {
  const std::string good = defaultText();
  expectError("", {"bad.yaml", "empty"});
  expectError("segments: [", {"bad.yaml:", "not valid YAML"});
  expectError("- 1\n- 2\n", {"bad.yaml:1:1", "(top level)", "mapping"});
  expectError(replaced(good, "name: default adult", "name: default adult\ncolour: pink"),
              {"bad.yaml:", "colour", "unknown key"});
  expectError(replaced(good, "  - bone: body ", "  - bone: tail "), {"segments.tail", "no bone"});
  expectError(replaced(good, "      - [-0.09, 0.100, 0.150]", "      - [-0.09, -0.100, 0.150]"),
              {"segments.body.sections[0]", "radii must be > 0"});
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [-0.10, 0.110, 0.165]"),
              {"segments.body.sections[1]", "greater than the previous"});
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [-0.01, 0.110]"),
              {"segments.body.sections[1]", "3 numbers"});
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [-0.01, 0.110, wide]"),
              {"segments.body.sections[1][2]", "expected a number"});
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [-0.01, 0.110, 165]"),
              {"segments.body.sections[1]", "metres"});
  // The waist's joint is at z = 0.05 in the body frame: the pelvis region must stop below it.
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [0.07, 0.110, 0.165]"),
              {"segments.body.sections", "below the joint", "waist"});
  expectError(
      replaced(good, "  - bone: waist           # 0.20 m, z up\n    joined: true\n    sections:\n      - [0.00,",
               "  - bone: waist           # 0.20 m, z up\n    joined: true\n    sections:\n      - [0.02,"),
      {"segments.waist.sections[0]", "z must be 0"});
  expectError(replaced(good, "    joined: true\n    distal_cap: 0.10", "    joined: true\n    distal_cap: 0.0"),
              {"segments.head.distal_cap", "open distal end"});
  expectError(replaced(good, "    proximal_cap: 0.06    # crotch", "    proximal_cap: -0.06"),
              {"segments.body.proximal_cap", ">= 0"});
  // Sizes no person has (issue 23): they would put the skin's control points at 1e300 m.
  expectError(replaced(good, "    proximal_cap: 0.06    # crotch", "    proximal_cap: 1e300"),
              {"segments.body.proximal_cap", "1e+300 m is outside [0, 1] m"});
  expectError(replaced(good, "      - [-0.01, 0.110, 0.165]", "      - [-1e300, 0.110, 0.165]"),
              {"sections[", "[0]: -1e+300 m (z along the bone) is outside [-1, 1]"});
  expectError(replaced(good, "    proximal_cap: 0.06    # crotch", "    joined: true"),
              {"segments.body.joined", "no parent"});
  expectError(replaced(good, "    joined: true\n    sections:\n      - [0.00, 0.050, 0.055]",
                       "    joined: yes please\n    sections:\n      - [0.00, 0.050, 0.055]"),
              {"segments.neck.joined", "true or false"});
  // A clavicle starts beside the spine, off the chest's axis: it cannot continue the chest.
  expectError(replaced(good, "  - bone: l_clavicle      # 0.17 m\n    proximal_cap: 0.03",
                       "  - bone: l_clavicle      # 0.17 m\n    joined: true"),
              {"segments.l_clavicle.joined"});
  expectError(replaced(good, "    joined: true\n    sections:\n      - [0.00, 0.050, 0.055]",
                       "    joined: true\n    proximal_cap: 0.02\n    sections:\n      - [0.00, 0.050, 0.055]"),
              {"segments.neck.proximal_cap", "no proximal cap"});
  expectError(replaced(good, "  - bone: r_clavicle\n", "  - bone: l_clavicle\n"),
              {"segments.l_clavicle", "second segment"});
  expectError(replaced(good, "  all: [1.0, 1.0, 1.0]", "  tentacles: [1.0, 1.0, 1.0]"),
              {"bad.yaml:", "shape.tentacles", "neither a bone"});
  expectError(replaced(good, "  all: [1.0, 1.0, 1.0]", "  arms: [1.0, 0.0, 1.0]"), {"shape.arms", "outside"});
  expectError("name: x\nsegments: {}\n", {"bad.yaml:2:11", "segments", "non-empty list"});
  // A child listed before its parent.
  const std::string neck_and_head =
      "  - bone: neck            # 0.09 m\n    joined: true\n    sections:\n      - [0.00, 0.050, 0.055]\n";
  std::string reordered = replaced(good, neck_and_head, "");
  reordered = replaced(reordered, "  # ---- shoulders", neck_and_head + "  # ---- shoulders");
  expectError(reordered, {"segments.head.joined", "must come earlier"});
  EXPECT_THROW(loadBodyDescriptionFile("/nonexistent/body.yaml", skeleton()), BodyDescriptionError);
}

}  // namespace
}  // namespace dressed_human
