#pragma once
// Recorded pedestrian trajectories in the two text formats the crowd datasets ship in:
//  - Jülich / PedPy / PeTrack: '#' comment lines, whose header states the frame rate
//    ("# framerate: 25 fps") and may state the unit ("# id frame x/cm y/cm z/cm"; metres when it
//    states none), then `id frame x y [z]` per line, tab or space separated;
//  - ETH/UCY obsmat.txt: `frame id x z y vx vz vy` per line (8 numbers, often in scientific
//    notation), no header, metres. Its frame numbers are video frames annotated every 6 or 10
//    frames; the annotations are 2.5 Hz apart (the datasets' papers), the video rate differs.
// Time: one step of the frame numbers (their greatest common gap: 1 in the Jülich files, 10 or 6
// in obsmat files) is 1/sample_rate seconds, counted from the first frame. A Jülich file's rate is
// frames per second of its frame numbers; an obsmat file's is samples per second (2.5 Hz unless
// one is given).

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace dressed_human {

struct PedestrianTrajectoryError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class TrajectoryFormat { kAuto, kJuelich, kObsmat };

// "auto", "juelich", "obsmat" and back; an unknown name throws PedestrianTrajectoryError listing them.
TrajectoryFormat trajectoryFormatNamed(const std::string& name);
const char* trajectoryFormatName(TrajectoryFormat format);

struct TrajectoryReadOptions {
  TrajectoryFormat format = TrajectoryFormat::kAuto;  // kAuto: from the columns of the first row
  // Hz, > 0 overrides the file's: a Jülich file's frames per second, an obsmat file's samples per
  // second. 0: the Jülich header's statement, 2.5 Hz for obsmat.
  double frame_rate = 0.0;
};

struct TrajectorySample {
  std::size_t step = 0;  // samples since the file's first frame: (frame - first_frame) / frame_step
  double time = 0.0;     // s since the file's first frame: step / sample_rate
  // m; x, y on the floor; z as the file gives it (PeTrack: a head height, often the same for
  // everyone; obsmat: 0), 0 when it gives none.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

struct PersonTrajectory {
  std::uint64_t id = 0;
  std::vector<TrajectorySample> samples;  // by time, one per frame the person is in
};

struct PedestrianTrajectories {
  TrajectoryFormat format = TrajectoryFormat::kAuto;  // the one read (never kAuto)
  double sample_rate = 0.0;                           // Hz: samples (frame steps) per second
  std::int64_t first_frame = 0;                       // the file's frame numbers
  std::int64_t last_frame = 0;
  std::int64_t frame_step = 1;
  std::vector<PersonTrajectory> people;  // by id

  std::size_t sampleCount() const { return static_cast<std::size_t>((last_frame - first_frame) / frame_step) + 1; }
  double duration() const { return static_cast<double>(sampleCount() - 1) / sample_rate; }  // s, first to last sample
};

// The most samples a recording may span (11 hours at 25 Hz): a frame number past that is taken
// for a typo rather than filled with millions of empty samples.
constexpr std::size_t kMaxTrajectorySamples = 1000000;

// Throws PedestrianTrajectoryError "source:line: what is wrong" for a row that does not parse (a
// column count neither format has, or not the one of the first row; a non-number; NaN or
// infinity; an id or frame that is not a whole number >= 0), a person twice in one frame, a
// header frame rate or unit that does not parse; "source: ..." for no rows at all and for a
// Jülich file without a frame rate (neither stated nor given).
PedestrianTrajectories parsePedestrianTrajectories(std::string_view text, const std::string& source_name,
                                                   const TrajectoryReadOptions& options = {});
// The file's text parsed as above; also throws when it cannot be read.
PedestrianTrajectories loadPedestrianTrajectories(const std::string& path, const TrajectoryReadOptions& options = {});

}  // namespace dressed_human
