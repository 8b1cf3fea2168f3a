// OpenSim .mot parsing: the gait tutorial file reads completely; malformed input is rejected with
// file and line.
#include <gtest/gtest.h>

#include <string>

#include "dressed_human/core/motion/opensim_motion_file.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;

const std::string kHeader = "demo\nversion=1\nnRows=2\nnColumns=3\ninDegrees=yes\nendheader\n";

std::string errorOf(const std::string& text) {
  try {
    parseOpenSimMotion(text, "test.mot");
  } catch (const OpenSimError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(OpenSimMotionFile, GaitCycleReadsCompletely) {
  const OpenSimTable table = loadOpenSimMotionFile(kSource + "/data/motion/tutorial_normal_gait_cycle.mot");
  EXPECT_EQ(table.name, "normal_gait");
  EXPECT_TRUE(table.in_degrees);
  EXPECT_EQ(table.labels.size(), 18u);
  EXPECT_EQ(table.rows.size(), 51u);
  EXPECT_DOUBLE_EQ(table.times.front(), 0.0);
  EXPECT_DOUBLE_EQ(table.times.back(), 1.0);
  const int knee = table.findColumn("knee_angle_l");
  ASSERT_GE(knee, 0);
  EXPECT_DOUBLE_EQ(table.rows[0][static_cast<std::size_t>(knee)], -8.2);
  EXPECT_EQ(table.column(static_cast<std::size_t>(knee)).size(), 51u);
}

TEST(OpenSimMotionFile, RadiansHeader) {
  const OpenSimTable table = parseOpenSimMotion("inDegrees=no\nendheader\ntime\tq\n0\t0.1\n0.5\t0.2\n", "radians.mot");
  EXPECT_FALSE(table.in_degrees);
  EXPECT_EQ(table.rows.size(), 2u);
}

struct BadMot {
  std::string text;
  std::string expected;
};

class BadMotFile : public ::testing::TestWithParam<BadMot> {};

TEST_P(BadMotFile, IsRejectedWithItsMessage) {
  const std::string message = errorOf(GetParam().text);
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
  EXPECT_EQ(message.rfind("test.mot:", 0), 0u) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, BadMotFile,
    ::testing::Values(BadMot{"", "no 'endheader'"}, BadMot{"inDegrees=yes\ntime a\n0 1\n", "no 'endheader'"},
                      BadMot{"version=1\nendheader\ntime a b\n0 1 2\n1 2 3\n", "inDegrees"},
                      BadMot{"inDegrees=maybe\nendheader\n", "must be 'yes' or 'no'"},
                      BadMot{kHeader + "time a b\n0 1 2\n", "nRows=2 but there are 1"},
                      BadMot{kHeader + "time a\n0 1\n1 2\n", "nColumns=3 but there are 2"},
                      BadMot{kHeader + "t a b\n0 1 2\n1 2 3\n", "first column label must be 'time'"},
                      BadMot{kHeader + "time a a\n0 1 2\n1 2 3\n", "appears twice"},
                      BadMot{kHeader + "time a b\n0 1 2\n1 2\n", "row has 2 values, expected 3"},
                      BadMot{kHeader + "time a b\n0 1 x\n1 2 3\n", "column 'b': expected a number, got 'x'"},
                      BadMot{kHeader + "time a b\n0 1 inf\n1 2 3\n", "finite"},
                      BadMot{kHeader + "time a b\n1 1 2\n1 2 3\n", "does not increase"},
                      BadMot{"inDegrees=yes\nendheader\ntime a\n", "no data rows"},
                      BadMot{"inDegrees=yes\nendheader\n", "no column labels"},
                      BadMot{"inDegrees=yes\nnRows=1x\nendheader\n", "nRows must be a whole number"}));

TEST(OpenSimMotionFile, ErrorsNameTheLine) {
  EXPECT_NE(errorOf(kHeader + "time a b\n0 1 2\n1 2 oops\n").find("test.mot:9:"), std::string::npos);
}

}  // namespace
}  // namespace dressed_human
