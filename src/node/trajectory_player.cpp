#include "trajectory_player.h"

#include <algorithm>

#include "parameters.h"
#include "tick_clock.h"

namespace dressed_human {
namespace {

constexpr double kMaxRate = 1000.0;  // Hz: messages per second, and the largest frame rate one may give
constexpr double kMinTimeScale = 0.01;
constexpr double kMaxTimeScale = 100.0;

}  // namespace

TrajectoryPlayerSettings TrajectoryPlayerSettings::fromParameters(const ros::NodeHandle& private_node) {
  const Parameters parameters(private_node);
  TrajectoryPlayerSettings s;
  s.file = parameters.requiredText("file");
  if (s.file.empty())
    throw ParameterError("parameter " + parameters.fullName("file") + " is empty: give a trajectory file");
  const std::string format = parameters.text("format", "auto");
  try {
    s.read.format = trajectoryFormatNamed(format);
  } catch (const PedestrianTrajectoryError&) {
    throw ParameterError("parameter " + parameters.fullName("format") + " must be auto, juelich or obsmat, got '" +
                         format + "'");
  }
  s.read.frame_rate = parameters.numberIn("frame_rate", 0.0, 0.0, kMaxRate, "Hz (0: the file's)");
  s.loop = parameters.boolean("loop", s.loop);
  s.time_scale = parameters.numberIn("time_scale", s.time_scale, kMinTimeScale, kMaxTimeScale, "");
  s.placement.offset = {parameters.number("offset_x", 0.0), parameters.number("offset_y", 0.0)};
  s.placement.yaw = parameters.number("yaw", 0.0);
  s.frame_id = parameters.text("frame_id", s.frame_id);
  if (s.frame_id.empty()) throw ParameterError("parameter " + parameters.fullName("frame_id") + " is empty");
  return s;
}

TrajectoryPlayer::TrajectoryPlayer(ros::NodeHandle node, ros::NodeHandle private_node)
    : settings_(TrajectoryPlayerSettings::fromParameters(private_node)),
      crowd_(loadRecording()),
      publish_rate_(crowd_.sampleRate() * settings_.time_scale) {
  if (publish_rate_ > kMaxRate) {
    const Parameters parameters(private_node);
    throw ParameterError("parameter " + parameters.fullName("time_scale") + " makes " + std::to_string(publish_rate_) +
                         " messages per second of " + settings_.file + " (" + std::to_string(crowd_.sampleRate()) +
                         " Hz): more than the " + std::to_string(static_cast<int>(kMaxRate)) + " the player sends");
  }
  std::size_t most_present = 0;
  for (std::size_t sample = 0; sample < crowd_.sampleCount(); ++sample)
    most_present = std::max(most_present, crowd_.countAt(sample));
  persons_.reserve(most_present);
  // The advertised type comes from a message: an empty one of the type every tick sends.
  const topic_tools::ShapeShifter type = encodeTrackedPersons(ros::Time(), settings_.frame_id, {});
  publisher_ = type.advertise(node, "tracked_persons", 10);
  ROS_INFO("trajectory_player: %s (%s): %zu persons, %.1f s in %zu samples at %g Hz, played at %g Hz on %s in %s%s",
           settings_.file.c_str(), trajectoryFormatName(settings_.read.format), crowd_.personCount(), crowd_.duration(),
           crowd_.sampleCount(), crowd_.sampleRate(), publish_rate_, publisher_.getTopic().c_str(),
           settings_.frame_id.c_str(), settings_.loop ? ", looping" : "");
}

RecordedCrowd TrajectoryPlayer::loadRecording() {
  const PedestrianTrajectories recording = loadPedestrianTrajectories(settings_.file, settings_.read);
  settings_.read.format = recording.format;
  return RecordedCrowd(recording, settings_.placement);
}

void TrajectoryPlayer::run() {
  runAtRate(publish_rate_, [this] { tick(); });
}

void TrajectoryPlayer::tick() {
  const ros::Time now = ros::Time::now();
  if (now.isZero()) return;  // simulated time has not started
  if (next_sample_ == crowd_.sampleCount()) {
    if (!settings_.loop) return;
    next_sample_ = 0;
    ++loops_;
    ROS_INFO("trajectory_player: %s from the start again (loop %zu; the stamps go on)", settings_.file.c_str(),
             loops_ + 1);
  }
  persons_.clear();
  for (const RecordedPerson* person = crowd_.begin(next_sample_); person != crowd_.end(next_sample_); ++person) {
    TrackedPersonOut out;
    out.track_id = person->id;
    // On the floor: the recordings' z is a head height (PeTrack's assumed one, often the same for all).
    out.position = Eigen::Vector3d(person->position.x(), person->position.y(), 0.0);
    // As fast as the people move in ROS time: a tracker reading the stream would measure that.
    out.velocity = Eigen::Vector3d(person->velocity.x(), person->velocity.y(), 0.0) * settings_.time_scale;
    out.yaw = person->heading;
    persons_.push_back(out);
  }
  publisher_.publish(encodeTrackedPersons(now, settings_.frame_id, persons_));
  if (++next_sample_ == crowd_.sampleCount() && !settings_.loop) {
    ROS_INFO("trajectory_player: %s played to its end; loop is false: no more messages", settings_.file.c_str());
  }
}

}  // namespace dressed_human
