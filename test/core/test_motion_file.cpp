// Motion files: a valid file loads; every kind of bad input is rejected with a message naming the
// file, the line and the key.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "dressed_human/core/motion/motion_file.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
const std::string kBadDir = kSource + "/test/data/bad_motions/";

std::string errorOf(const std::string& path) {
  try {
    loadMotionFile(path);
  } catch (const MotionError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string errorOfText(const std::string& text) {
  try {
    parseMotionYaml(text, "inline.yaml");
  } catch (const MotionError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string validText() {
  Motion motion;
  motion.period = 1.1;
  motion.dofs[0].a = {0.1, 0.2};
  motion.dofs[0].b = {0.0, -0.1};
  motion.root.forward_speed = 1.2;
  motion.root.translation[2].a0 = 1.86;
  std::ostringstream text;
  writeMotionYaml(motion, text);
  return text.str();
}

void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

TEST(MotionFile, ShippedWalkLoads) {
  const Motion walk = loadMotionFile(kSource + "/config/motions/walk.yaml");
  EXPECT_GT(walk.period, 0.5);
  EXPECT_LT(walk.period, 2.0);
  EXPECT_GT(walk.root.forward_speed, 0.3);
}

TEST(MotionFile, WrittenMotionReadsBackIdentically) {
  const Motion read = parseMotionYaml(validText(), "inline.yaml");
  EXPECT_EQ(read.period, 1.1);
  ASSERT_EQ(read.dofs[0].order(), 2u);
  EXPECT_EQ(read.dofs[0].a[1], 0.2);
  EXPECT_EQ(read.dofs[0].b[1], -0.1);
  EXPECT_EQ(read.root.translation[2].a0, 1.86);
  EXPECT_EQ(read.root.forward_speed, 1.2);
}

struct BadFile {
  const char* file;
  const char* expected;  // a part of the message
};

class BadMotionFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadMotionFile, IsRejectedWithItsMessage) {
  const BadFile bad = GetParam();
  const std::string message = errorOf(kBadDir + bad.file);
  EXPECT_NE(message.find(bad.file), std::string::npos) << "the file is not named: " << message;
  EXPECT_NE(message.find(bad.expected), std::string::npos) << "expected '" << bad.expected << "' in: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    AllKinds, BadMotionFile,
    ::testing::Values(
        BadFile{"syntax_error.yaml", ":3:1: not valid YAML"}, BadFile{"empty.yaml", "the motion file is empty"},
        BadFile{"unknown_top_key.yaml",
                ":4:1: speed: unknown key; expected one of: body_shape, joints, name, period, root"},
        BadFile{"missing_period.yaml", "period: missing"},
        BadFile{"negative_period.yaml", ":1:9: period: must be > 0 seconds, got -1.1"},
        BadFile{"period_not_number.yaml", ":1:9: period: expected a number, got 'fast'"},
        BadFile{"period_infinite.yaml", "period: expected a finite number, got '.inf'"},
        BadFile{"unknown_joint.yaml", ":3:3: joints.l_hipp: unknown key"},
        BadFile{"missing_joint.yaml", "joints.waist: missing"}, BadFile{"missing_dof.yaml", "joints.waist.z: missing"},
        BadFile{"unknown_dof.yaml", ":5:5: joints.waist.w: unknown key; expected one of: x, y, z"},
        BadFile{"coefficient_count.yaml", ":4:8: joints.waist.y: wrong coefficient counts: 2 in a but 1 in b"},
        BadFile{"coefficient_nan.yaml", ":4:25: joints.waist.y.a[2]: expected a finite number, got '.nan'"},
        BadFile{"missing_a0.yaml", "joints.waist.y.a0: missing"},
        BadFile{"a0_wrong_type.yaml", ":4:13: joints.waist.y.a0: expected a number, got 'zero'"},
        BadFile{"coefficients_not_list.yaml", "joints.waist.y.a: expected a list of numbers, got '0.5'"},
        BadFile{"dof_period_zero.yaml", "joints.waist.y.period: must be > 0 seconds"},
        BadFile{"joint_not_mapping.yaml", ":3:10: joints.waist: expected a mapping"}),
    [](const ::testing::TestParamInfo<BadFile>& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(MotionFile, MissingFileIsNamed) {
  EXPECT_NE(errorOf("/nonexistent/walk.yaml").find("/nonexistent/walk.yaml: cannot open the motion file"),
            std::string::npos);
}

TEST(MotionFile, RootErrorsNameTheKey) {
  std::string text = validText();
  replaceOnce(text, "forward_speed: 1.2", "forward_speed: slow");
  EXPECT_NE(errorOfText(text).find("root.forward_speed: expected a number, got 'slow'"), std::string::npos)
      << errorOfText(text);

  text = validText();
  replaceOnce(text, "    yaw: ", "    yawn: ");
  EXPECT_NE(errorOfText(text).find("root.rotation.yawn: unknown key"), std::string::npos) << errorOfText(text);
}

TEST(MotionFile, ProgrammaticMotionIsValidated) {
  Motion motion;
  motion.dofs[4 * 3 + 2].a = {1.0};  // l_shoulder (joint 4), DOF z
  std::ostringstream out;
  try {
    writeMotionYaml(motion, out);
    FAIL() << "an inconsistent motion was written";
  } catch (const MotionError& error) {
    EXPECT_NE(std::string(error.what()).find("l_shoulder.z: 1 cosine coefficients but 0 sine"), std::string::npos)
        << error.what();
  }
}

// Issue 23: numbers a person cannot have are rejected with the key, the value and the range.
TEST(MotionFile, AbsurdNumbersAreRejectedWithTheirRange) {
  struct Case {
    std::string from, to, expected;
  };
  const std::vector<Case> cases = {
      {"period: 1.1000000000000001", "period: 1e-300", "motion period 1e-300 s is outside [0.1, 60] s"},
      {"period: 1.1000000000000001", "period: 1e5", "motion period 100000 s is outside [0.1, 60] s"},
      {"{a0: 0, period: 1}", "{a0: 0, period: 1e-300}", "waist.x: period 1e-300 s is outside [0.1, 60] s"},
      {"forward_speed: 1.2", "forward_speed: 1e300", "root.forward_speed 1e+300 m/s is outside [-12.5, 12.5] m/s"},
      {"a0: 1.8600000000000001", "a0: 1e308",
       "root.translation.z: amplitude 0.5 |a0| + sum |(a_k, b_k)| = 5e+307 m is outside [0, 10] m"},
      {"0.20000000000000001]", "200]",
       "waist.y: amplitude 0.5 |a0| + sum |(a_k, b_k)| = 200.1 rad is outside [0, 6.28319] rad"},
  };
  for (const Case& c : cases) {
    std::string text = validText();
    replaceOnce(text, c.from, c.to);
    const std::string message = errorOfText(text);
    EXPECT_NE(message.find("inline.yaml: " + c.expected), std::string::npos) << c.to << " gave: " << message;
  }
}

TEST(MotionFile, AnOrderAboveWhatACaptureHoldsIsRejected) {
  std::string text = validText();
  std::string a = "a: [", b = "b: [";
  for (std::size_t k = 0; k < MotionLimits::kMaxOrder + 1; ++k) {
    a += (k ? ", " : "") + std::string("0");
    b += (k ? ", " : "") + std::string("0");
  }
  replaceOnce(text, "a: [0.10000000000000001, 0.20000000000000001]", a + "]");
  replaceOnce(text, "b: [0, -0.10000000000000001]", b + "]");
  EXPECT_NE(errorOfText(text).find("waist.y: order 65 is above 64"), std::string::npos) << errorOfText(text);
}

TEST(MotionFile, ADuplicatedKeyNamesBothLines) {
  std::string text = validText();
  text = "name: first\n" + text + "name: again\n";
  const std::string message = errorOfText(text);
  EXPECT_NE(message.find("inline.yaml:"), std::string::npos) << message;
  EXPECT_NE(message.find(": name: the key appears twice (first at line 1)"), std::string::npos) << message;
  std::string nested = validText();
  replaceOnce(nested, "forward_speed: 1.2", "forward_speed: 1.2\n  forward_speed: 9");
  EXPECT_NE(errorOfText(nested).find("root.forward_speed: the key appears twice"), std::string::npos)
      << errorOfText(nested);
}

}  // namespace
}  // namespace dressed_human
