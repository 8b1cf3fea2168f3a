#include "dressed_human/core/io/pedestrian_trajectories.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "temp_file_path.h"

namespace dressed_human {
namespace {

const std::string kSharedPeople = std::string(DRESSED_HUMAN_SHARED_DIR) + "/data/people/";

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = tempFilePath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

PedestrianTrajectories load(const std::string& text, const TrajectoryReadOptions& options = {}) {
  const std::string path = writeFile("trajectories.txt", text);
  PedestrianTrajectories result = loadPedestrianTrajectories(path, options);
  std::remove(path.c_str());
  return result;
}

// The error's message with the temporary file's path replaced by "file".
std::string errorOf(const std::string& text, const TrajectoryReadOptions& options = {}) {
  const std::string path = writeFile("bad_trajectories.txt", text);
  std::string message = "(no error)";
  try {
    loadPedestrianTrajectories(path, options);
  } catch (const PedestrianTrajectoryError& error) {
    message = error.what();
    if (message.compare(0, path.size(), path) == 0) message = "file" + message.substr(path.size());
  }
  std::remove(path.c_str());
  return message;
}

TrajectoryReadOptions withRate(double frame_rate, TrajectoryFormat format = TrajectoryFormat::kAuto) {
  TrajectoryReadOptions options;
  options.format = format;
  options.frame_rate = frame_rate;
  return options;
}

TrajectoryReadOptions withFormat(TrajectoryFormat format) { return withRate(0.0, format); }

const char* const kPeTrackFile =
    "# PeTrack project: test.pet\n"
    "# framerate: 25 fps\n"
    "# id frame x/m y/m z/m\n"
    "2\t11\t5.0\t1.5\t1.70\n"
    "1\t10\t0.5\t-1.0\t1.76\n"
    "1 11   0.54  -1.0 1.76\n"  // spaces work as well as tabs
    "2\t12\t4.96\t1.5\t1.70\n"
    "1\t12\t0.58\t-1.0\t1.76\n";

TEST(PedestrianTrajectories, APeTrackFileGivesEachPersonsSamplesInTimeFromTheFirstFrame) {
  const PedestrianTrajectories t = load(kPeTrackFile);
  EXPECT_EQ(t.format, TrajectoryFormat::kJuelich);
  EXPECT_DOUBLE_EQ(t.sample_rate, 25.0);
  EXPECT_EQ(t.first_frame, 10);
  EXPECT_EQ(t.last_frame, 12);
  EXPECT_EQ(t.frame_step, 1);
  EXPECT_EQ(t.sampleCount(), 3u);
  EXPECT_DOUBLE_EQ(t.duration(), 0.08);
  ASSERT_EQ(t.people.size(), 2u);
  EXPECT_EQ(t.people[0].id, 1u);  // by id, whatever the rows' order
  ASSERT_EQ(t.people[0].samples.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(t.people[0].samples[i].step, i);
    EXPECT_DOUBLE_EQ(t.people[0].samples[i].time, 0.04 * static_cast<double>(i));
  }
  EXPECT_TRUE(t.people[0].samples[1].position.isApprox(Eigen::Vector3d(0.54, -1.0, 1.76)));
  EXPECT_EQ(t.people[1].id, 2u);
  ASSERT_EQ(t.people[1].samples.size(), 2u);
  EXPECT_EQ(t.people[1].samples[0].step, 1u);  // frame 11: one frame after the file's first
  EXPECT_DOUBLE_EQ(t.people[1].samples[0].time, 0.04);
  EXPECT_TRUE(t.people[1].samples[1].position.isApprox(Eigen::Vector3d(4.96, 1.5, 1.70)));
}

TEST(PedestrianTrajectories, APedPyFileWithoutZAndWindowsLineEndsReads) {
  const PedestrianTrajectories t = load(
      "# description: UNI_CORR_500_01\r\n# framerate: 25.00\r\n#geometry: geometry.xml\r\n\r\n"
      "# PersID\tFrame\tX\tY\r\n7\t98\t4.6012\t1.8909\r\n7\t99\t4.5359\t1.8976\r\n");
  EXPECT_DOUBLE_EQ(t.sample_rate, 25.0);
  ASSERT_EQ(t.people.size(), 1u);
  EXPECT_EQ(t.people[0].id, 7u);
  EXPECT_TRUE(t.people[0].samples[1].position.isApprox(Eigen::Vector3d(4.5359, 1.8976, 0.0)));
}

TEST(PedestrianTrajectories, APeTrackFileInCentimetresIsReadInMetres) {
  const PedestrianTrajectories t = load("# framerate: 25 fps\n# id frame x/cm y/cm z/cm\n1 0 250 -40 176\n");
  EXPECT_TRUE(t.people[0].samples[0].position.isApprox(Eigen::Vector3d(2.5, -0.4, 1.76)));
  const PedestrianTrajectories units = load("# framerate: 25\n# unit: mm\n1 0 250 -40 1760\n");
  EXPECT_TRUE(units.people[0].samples[0].position.isApprox(Eigen::Vector3d(0.25, -0.04, 1.76)));
}

TEST(PedestrianTrajectories, AGivenFrameRateOverridesTheHeaderAndIsNeededWithoutOne) {
  EXPECT_DOUBLE_EQ(load(kPeTrackFile, withRate(50.0)).people[0].samples[2].time, 0.04);
  const std::string no_rate = "# id frame x/m y/m z/m\n1 0 0 0 1.7\n1 1 0.04 0 1.7\n";
  EXPECT_EQ(errorOf(no_rate),
            "file: the header states no frame rate (a line such as '# framerate: 25 fps'): give the recording's frames "
            "per second (frame_rate)");
  EXPECT_DOUBLE_EQ(load(no_rate, withRate(10.0)).people[0].samples[1].time, 0.1);
}

TEST(PedestrianTrajectories, FramesThatStepBySeveralAreOneSampleAStep) {
  const PedestrianTrajectories t = load("# framerate: 25 fps\n1 4 0 0 0\n1 6 0 0 0\n1 10 0 0 0\n");
  EXPECT_EQ(t.frame_step, 2);
  EXPECT_DOUBLE_EQ(t.sample_rate, 12.5);
  EXPECT_EQ(t.sampleCount(), 4u);
  EXPECT_EQ(t.people[0].samples[2].step, 3u);  // frame 8 is missing: the time is still the frame's
  EXPECT_DOUBLE_EQ(t.people[0].samples[2].time, 0.24);
}

// ETH's seq_hotel style: every 10th video frame annotated, scientific notation, x z y columns.
const char* const kObsmatFile =
    "   7.8000000e+02   1.0000000e+00   8.4556575e+00   0.0000000e+00   3.5863173e+00   1.6075000e+00   0.0000000e+00  "
    "-1.4800000e-01\n"
    "   7.9000000e+02   1.0000000e+00   9.0986576e+00   0.0000000e+00   3.5271269e+00   1.6075000e+00   0.0000000e+00  "
    "-1.4800000e-01\n"
    "   7.9000000e+02   2.0000000e+00   1.0000000e+00   0.0000000e+00   2.0000000e+00   0.0000000e+00   0.0000000e+00  "
    " 0.0000000e+00\n"
    "   8.1000000e+02   1.0000000e+00   9.7416577e+00   0.0000000e+00   3.4679364e+00   1.6075000e+00   0.0000000e+00  "
    "-1.4800000e-01\n";

TEST(PedestrianTrajectories, AnObsmatFileIsSampledAt2point5HzOneStepOfItsFrameNumbersApart) {
  const PedestrianTrajectories t = load(kObsmatFile);
  EXPECT_EQ(t.format, TrajectoryFormat::kObsmat);
  EXPECT_DOUBLE_EQ(t.sample_rate, 2.5);
  EXPECT_EQ(t.first_frame, 780);
  EXPECT_EQ(t.frame_step, 10);
  EXPECT_EQ(t.sampleCount(), 4u);  // 780, 790, (800: nobody annotated), 810
  ASSERT_EQ(t.people.size(), 2u);
  const PersonTrajectory& first = t.people[0];
  ASSERT_EQ(first.samples.size(), 3u);
  EXPECT_DOUBLE_EQ(first.samples[1].time, 0.4);
  EXPECT_DOUBLE_EQ(first.samples[2].time, 1.2);
  EXPECT_TRUE(
      first.samples[0].position.isApprox(Eigen::Vector3d(8.4556575, 3.5863173, 0.0)));  // x, then y from column 5
  EXPECT_EQ(t.people[1].samples[0].step, 1u);
  // A given rate is samples per second here: one step of the frame numbers.
  EXPECT_DOUBLE_EQ(load(kObsmatFile, withRate(5.0)).people[0].samples[1].time, 0.2);
}

TEST(PedestrianTrajectories, TheFormatCanBeGivenAndMustMatchTheColumns) {
  EXPECT_EQ(load(kObsmatFile, withFormat(TrajectoryFormat::kObsmat)).format, TrajectoryFormat::kObsmat);
  EXPECT_EQ(load(kPeTrackFile, withFormat(TrajectoryFormat::kJuelich)).format, TrajectoryFormat::kJuelich);
  EXPECT_EQ(errorOf(kObsmatFile, withFormat(TrajectoryFormat::kJuelich)),
            "file:1: 8 columns; the Jülich format has 4 or 5: id frame x y [z]");
  EXPECT_EQ(errorOf(kPeTrackFile, withFormat(TrajectoryFormat::kObsmat)),
            "file:4: 5 columns; the obsmat format has 8: frame id x z y vx vz vy");
  EXPECT_EQ(errorOf("# framerate: 25\n1 2 3 4 5 6\n"),
            "file:2: 6 columns: neither the Jülich format (id frame x y [z], 4 or 5) nor obsmat (frame id x z y vx vz "
            "vy, 8)");
  EXPECT_EQ(trajectoryFormatNamed("obsmat"), TrajectoryFormat::kObsmat);
  EXPECT_STREQ(trajectoryFormatName(trajectoryFormatNamed("juelich")), "juelich");
  EXPECT_THROW(trajectoryFormatNamed("eth"), PedestrianTrajectoryError);
}

TEST(PedestrianTrajectories, AMalformedRowNamesItsFileLineAndColumn) {
  const std::string header = "# framerate: 25 fps\n";
  EXPECT_EQ(errorOf(header + "1 0 0 0 1.7\n1 1 0.04 abc 1.7\n"), "file:3: column y is not a number: 'abc'");
  EXPECT_EQ(errorOf(header + "1 0 0 0 1.7\n1 1 0.04 0.5x 1.7\n"), "file:3: column y is not a number: '0.5x'");
  EXPECT_EQ(errorOf(header + "1 0 0 0 1.7\n1 1 0.04 0\n"), "file:3: 4 columns, the first row (line 2) has 5");
  EXPECT_EQ(errorOf(header + "1.5 0 0 0 1.7\n"), "file:2: column id must be a whole number >= 0, got '1.5'");
  EXPECT_EQ(errorOf(header + "1 -3 0 0 1.7\n"), "file:2: column frame must be a whole number >= 0, got '-3'");
  EXPECT_EQ(errorOf(header + "1 0 1e999 0 1.7\n"), "file:2: column x is out of a double's range: '1e999'");
  EXPECT_EQ(errorOf(std::string(kObsmatFile) + "8.2e+02 1 9.9 0 3.4 1.6 0 zz\n"),
            "file:5: column vy is not a number: 'zz'");
}

TEST(PedestrianTrajectories, NotANumberAndInfinityAreRefused) {
  EXPECT_EQ(errorOf("# framerate: 25 fps\n1 0 nan 0 1.7\n"), "file:2: column x is not finite: 'nan'");
  EXPECT_EQ(errorOf("# framerate: 25 fps\n1 0 0 -inf 1.7\n"), "file:2: column y is not finite: '-inf'");
  EXPECT_EQ(errorOf("# framerate: 25 fps\n1 0 0 0 NaN\n"), "file:2: column z is not finite: 'NaN'");
}

TEST(PedestrianTrajectories, APersonTwiceInOneFrameNamesBothLines) {
  EXPECT_EQ(errorOf("# framerate: 25 fps\n1 0 0 0 1.7\n2 0 1 0 1.7\n1 1 0 0 1.7\n1 0 0.1 0 1.7\n"),
            "file:5: person 1 at frame 0 a second time (first at line 2)");
}

TEST(PedestrianTrajectories, AFileWithoutRowsSaysSo) {
  EXPECT_EQ(errorOf(""), "file: no trajectory rows (an empty file)");
  EXPECT_EQ(errorOf("# framerate: 25 fps\n\n   \n"), "file: no trajectory rows (only comments and blank lines)");
  const std::string missing = "/nonexistent/people.txt";
  try {
    loadPedestrianTrajectories(missing);
    FAIL() << "no error for a missing file";
  } catch (const PedestrianTrajectoryError& error) {
    EXPECT_STREQ(error.what(), "/nonexistent/people.txt: cannot open the trajectory file: No such file or directory");
  }
}

TEST(PedestrianTrajectories, ABadHeaderStatementNamesItsLine) {
  EXPECT_EQ(errorOf("#x\n# framerate: fast\n1 0 0 0 0\n"),
            "file:2: the frame rate statement holds no number: '# framerate: fast'");
  EXPECT_EQ(errorOf("# framerate: 0 fps\n1 0 0 0 0\n"),
            "file:1: the frame rate must be > 0 frames per second, the header states 0");
  EXPECT_EQ(errorOf("# framerate: 25\n# frame rate: 30\n1 0 0 0 0\n"),
            "file:2: states the frame rate 30, line 1 stated 25");
  EXPECT_EQ(errorOf("# framerate: 25\n# id frame x/cm y/m\n1 0 0 0\n"), "file:2: states the unit m, line 2 stated cm");
  EXPECT_EQ(errorOf("# framerate: 25\n# unit: ft\n1 0 0 0\n"), "file:2: the unit 'ft' is none of m, cm, mm");
  // Prose about the frame rate is no statement.
  EXPECT_DOUBLE_EQ(load("# the framerate was checked\n# framerate: 30\n1 0 0 0\n").sample_rate, 30.0);
}

TEST(PedestrianTrajectories, AFrameFarBeyondTheOthersOrABadGivenRateIsRefused) {
  EXPECT_EQ(errorOf("# framerate: 25\n1 0 0 0\n1 1 0 0\n2 5000000 0 0\n"),
            "file:4: frame 5000000 is 5000000 samples after the first (frame 0): more than the 1000000 a recording "
            "may span (a typo?)");
  EXPECT_EQ(errorOf(kPeTrackFile, withRate(-25.0)),
            "file: the given frame rate must be > 0 Hz (or 0: the file's), got -25");
}

// The two recordings shipped in /work/shared (their README states people, frames and rate).
TEST(PedestrianTrajectories, TheSharedJuelichRecordingsReadAsTheirReadmeSays) {
  struct stat status {};
  if (::stat(kSharedPeople.c_str(), &status) != 0) GTEST_SKIP() << "no shared recordings at " << kSharedPeople;
  struct Expected {
    const char* file;
    std::size_t people;
    std::int64_t first_frame, last_frame;
  };
  // The README says 149 people in the corridor; its file holds ids 1 to 148.
  for (const Expected& expected : {Expected{"juelich_uni_corr_500_01.txt", 148, 98, 1986},
                                   Expected{"juelich_bottleneck_040_c_56_h-.txt", 75, 0, 1656}}) {
    const auto start = std::chrono::steady_clock::now();
    const PedestrianTrajectories t = loadPedestrianTrajectories(kSharedPeople + expected.file);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    SCOPED_TRACE(expected.file);
    EXPECT_EQ(t.format, TrajectoryFormat::kJuelich);
    EXPECT_EQ(t.people.size(), expected.people);
    EXPECT_EQ(t.first_frame, expected.first_frame);
    EXPECT_EQ(t.last_frame, expected.last_frame);
    EXPECT_EQ(t.frame_step, 1);
    EXPECT_DOUBLE_EQ(t.sample_rate, 25.0);
    for (const PersonTrajectory& person : t.people) {
      for (std::size_t i = 1; i < person.samples.size(); ++i)
        EXPECT_GT(person.samples[i].time, person.samples[i - 1].time);
      EXPECT_DOUBLE_EQ(person.samples.front().position.z(), 1.76);
    }
#ifndef __SANITIZE_ADDRESS__  // ASan runs it several times slower: only the plain build is timed
    EXPECT_LT(seconds, 0.5);
#endif
  }
}

}  // namespace
}  // namespace dressed_human
