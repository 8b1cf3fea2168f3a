#pragma once
// The people messages of other packages, read and written without those packages (none is in
// Debian's archive): spencer_tracking_msgs/TrackedPersons (pedsim_msgs/TrackedPersons has the same
// layout and md5sum), pedsim_msgs/AgentStates and people_msgs/People. A topic of any of them is
// received as a topic_tools::ShapeShifter, its layout recognised by md5sum and decoded with
// roscpp's serialization. Their .msg texts, sources and licences: msg_layouts/.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <ros/time.h>
#include <topic_tools/shape_shifter.h>

namespace dressed_human {

struct PeopleMessageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One person of a people message, whatever its layout.
struct ObservedPerson {
  std::string id;  // a human id (isHumanId): a track / agent id in decimal, a People name sanitised (peopleNameId)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m, in the message's header frame
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s, same frame (what the source says; People: its velocity)
  std::optional<double> yaw;                           // rad about z, only where the source's orientation is valid
  bool occluded = false;  // TrackedPersons' is_occluded: its pose is the tracker's prediction
};

struct ObservedPeople {
  ros::Time stamp;
  std::string frame_id;
  std::vector<ObservedPerson> people;
};

enum class PeopleLayout { kTrackedPersons, kAgentStates, kPeople };

// The layout a topic's md5sum stands for; none if it is not one of them.
std::optional<PeopleLayout> peopleLayoutOf(const std::string& md5sum);
// "spencer_tracking_msgs/TrackedPersons or pedsim_msgs/TrackedPersons (md5 ...), ..." for errors.
std::string supportedPeopleTypes();

// Reads a received message. Throws PeopleMessageError naming `topic`, the message's type and the
// supported ones if the layout is unknown, and naming `topic` if the bytes do not hold the layout
// (truncated, or longer than it). pedsim's robot (AgentStates type 2) is left out.
ObservedPeople decodePeople(const topic_tools::ShapeShifter& message, const std::string& topic);

// A People name as a human id, the same every run: its letters and digits, and where that changed
// it (other characters, or none left) an 'x' and eight hex digits of a hash of the whole name, so
// that "a-b" and "ab" stay two people. A name that already ends like that ("abx0123abcd") gets
// the suffix too, so that it cannot be another name's id. The hash is 32-bit FNV-1a.
std::string peopleNameId(const std::string& name);

// What the trajectory player (and the tests) publish: spencer's TrackedPersons.
struct TrackedPersonOut {
  std::uint64_t track_id = 0;
  bool is_occluded = false;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  std::optional<double> yaw;  // none: orientation variance 99999 (unknown), as spencer marks it
};
// A ShapeShifter holding spencer_tracking_msgs/TrackedPersons (its md5sum, type and full
// definition set, so that rosbag records it as the real type), ready to publish
// (ShapeShifter::advertise advertises that type without its package).
topic_tools::ShapeShifter encodeTrackedPersons(const ros::Time& stamp, const std::string& frame_id,
                                               const std::vector<TrackedPersonOut>& persons);

}  // namespace dressed_human
