#include "people_messages.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include <ros/serialization.h>

namespace dressed_human {

namespace {

// The md5sums genmsg computes from the .msg texts in msg_layouts/ (what a publisher of those
// types announces). test/ros/test_people_message_layouts.py recomputes them from those texts and
// reads them from this file: keep each on one line as written.
constexpr char kTrackedPersonsMd5[] = "21c0b1a57c4933e68f39aa3802861828";
constexpr char kAgentStatesMd5[] = "aa81ea94344df8d81e135b65d4d499b1";
constexpr char kPeopleMd5[] = "18722f4b8db20cc2369740732357847b";

constexpr char kTrackedPersonsType[] = "spencer_tracking_msgs/TrackedPersons";

// genmsg's full definition of spencer_tracking_msgs/TrackedPersons (compute_full_text over
// msg_layouts/ and Debian's std_msgs and geometry_msgs), as a publisher of the real type sends it
// in its connection header: rosbag stores it, and tools that read a bag (rosbag's Python API,
// rqt_bag) build the message classes from it. The layout test checks it against genmsg's text.
constexpr char kTrackedPersonsDefinition[] = R"definition(# Message with all currently tracked persons 
#

Header              header      # Header containing timestamp etc. of this message
TrackedPerson[]     tracks      # All persons that are currently being tracked
================================================================================
MSG: std_msgs/Header
# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data 
# in a particular coordinate frame.
# 
# sequence ID: consecutively increasing ID 
uint32 seq
#Two-integer timestamp that is expressed as:
# * stamp.sec: seconds (stamp_secs) since epoch (in Python the variable is called 'secs')
# * stamp.nsec: nanoseconds since stamp_secs (in Python the variable is called 'nsecs')
# time-handling sugar is provided by the client library
time stamp
#Frame this data is associated with
string frame_id

================================================================================
MSG: spencer_tracking_msgs/TrackedPerson
# Message defining a tracked person
#

uint64      track_id        # unique identifier of the target, consistent over time
bool        is_occluded     # if the track is currently not observable in a physical way
bool        is_matched      # if the track is currently matched by a detection
uint64      detection_id    # id of the corresponding detection in the current cycle (undefined if occluded)
duration    age             # age of the track

# The following fields are extracted from the Kalman state x and its covariance C

geometry_msgs/PoseWithCovariance       pose   # pose of the track (z value and orientation might not be set, check if corresponding variance on diagonal is > 99999)

geometry_msgs/TwistWithCovariance   twist     # velocity of the track (z value and rotational velocities might not be set, check if corresponding variance on diagonal is > 99999)

================================================================================
MSG: geometry_msgs/PoseWithCovariance
# This represents a pose in free space with uncertainty.

Pose pose

# Row-major representation of the 6x6 covariance matrix
# The orientation parameters use a fixed-axis representation.
# In order, the parameters are:
# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)
float64[36] covariance

================================================================================
MSG: geometry_msgs/Pose
# A representation of pose in free space, composed of position and orientation. 
Point position
Quaternion orientation

================================================================================
MSG: geometry_msgs/Point
# This contains the position of a point in free space
float64 x
float64 y
float64 z

================================================================================
MSG: geometry_msgs/Quaternion
# This represents an orientation in free space in quaternion form.

float64 x
float64 y
float64 z
float64 w

================================================================================
MSG: geometry_msgs/TwistWithCovariance
# This expresses velocity in free space with uncertainty.

Twist twist

# Row-major representation of the 6x6 covariance matrix
# The orientation parameters use a fixed-axis representation.
# In order, the parameters are:
# (x, y, z, rotation about X axis, rotation about Y axis, rotation about Z axis)
float64[36] covariance

================================================================================
MSG: geometry_msgs/Twist
# This expresses velocity in free space broken into its linear and angular parts.
Vector3  linear
Vector3  angular

================================================================================
MSG: geometry_msgs/Vector3
# This represents a vector in free space. 
# It is only meant to represent a direction. Therefore, it does not
# make sense to apply a translation to it (e.g., when applying a 
# generic rigid transformation to a Vector3, tf2 will only apply the
# rotation). If you want your data to be translatable too, use the
# geometry_msgs/Point message instead.

float64 x
float64 y
float64 z)definition";

// spencer's TrackedPerson.msg: a value "might not be set, check if corresponding variance on
// diagonal is > 99999"; its tracker writes 99999 for an orientation it does not estimate.
constexpr double kUnknownVariance = 99999.0;
// The yaw's variance in a 6x6 row-major pose covariance (x, y, z, about x, about y, about z).
constexpr std::size_t kYawVarianceIndex = 5 * 6 + 5;
// A ground truth's variance (m², rad², (m/s)²): small, but not zero, because a consumer that
// inverts a track's covariance (a gating distance, an uncertainty ellipse) would find it singular.
constexpr double kGroundTruthVariance = 1e-4;
// pedsim_msgs/AgentState.msg: "2 -> Robot"; the robot is not a person to dress.
constexpr std::uint16_t kPedsimRobotType = 2;

// Bytes of the parts of each layout that have a fixed size.
constexpr std::uint32_t kVector3Bytes = 3 * 8;
constexpr std::uint32_t kQuaternionBytes = 4 * 8;
constexpr std::uint32_t kCovarianceBytes = 36 * 8;
// TrackedPerson: track_id, is_occluded, is_matched, detection_id, age, PoseWithCovariance,
// TwistWithCovariance.
constexpr std::uint32_t kTrackedPersonBytes =
    8 + 1 + 1 + 8 + 8 + (kVector3Bytes + kQuaternionBytes + kCovarianceBytes) + (2 * kVector3Bytes + kCovarianceBytes);
// The least an element of a variable-length layout can take: every string and array empty.
constexpr std::uint32_t kEmptyStringBytes = 4;
constexpr std::uint32_t kEmptyHeaderBytes = 4 + 8 + kEmptyStringBytes;
constexpr std::uint32_t kPedsimForcesBytes = 7 * kVector3Bytes;
constexpr std::uint32_t kSmallestAgentStateBytes = kEmptyHeaderBytes + 8 + 2 + kEmptyStringBytes +
                                                   (kVector3Bytes + kQuaternionBytes) + 2 * kVector3Bytes +
                                                   kPedsimForcesBytes;
constexpr std::uint32_t kSmallestPersonBytes = kEmptyStringBytes + 2 * kVector3Bytes + 8 + 2 * 4;

const char* layoutName(PeopleLayout layout) {
  switch (layout) {
    case PeopleLayout::kTrackedPersons:
      return "TrackedPersons";
    case PeopleLayout::kAgentStates:
      return "AgentStates";
    case PeopleLayout::kPeople:
      return "People";
  }
  return "?";
}

// Bytes that do not hold the layout they were announced as; decodePeople adds the topic.
struct MalformedBytes : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads a message's fields in order from its serialized bytes (little-endian, as roscpp writes
// them). Reading past the end throws roscpp's StreamOverrunException.
class FieldReader {
 public:
  explicit FieldReader(std::vector<std::uint8_t>& bytes)
      : stream_(bytes.data(), static_cast<std::uint32_t>(bytes.size())) {}

  template <typename Value>
  Value next() {
    Value value{};
    stream_.next(value);
    return value;
  }
  void skip(std::uint32_t bytes) { stream_.advance(bytes); }
  void skipString() { skip(next<std::uint32_t>()); }
  void skipStrings() {
    const std::uint32_t count = arrayLength(kEmptyStringBytes, "strings");
    for (std::uint32_t i = 0; i < count; ++i) skipString();
  }
  // An array's length, refused when even its smallest elements could not fit in the bytes left
  // (a corrupt count, or bytes of another layout): said at once, with the count, rather than as
  // an overrun somewhere inside the elements.
  std::uint32_t arrayLength(std::uint32_t smallest_element_bytes, const char* elements) {
    const std::uint32_t count = next<std::uint32_t>();
    if (std::uint64_t{count} * smallest_element_bytes > bytesLeft()) {
      throw MalformedBytes("an array of " + std::to_string(count) + " " + elements + " (at least " +
                           std::to_string(smallest_element_bytes) + " bytes each) in the " +
                           std::to_string(bytesLeft()) + " bytes left");
    }
    return count;
  }
  Eigen::Vector3d vector3() {
    Eigen::Vector3d vector;
    for (int i = 0; i < 3; ++i) vector[i] = next<double>();
    return vector;
  }
  // x, y, z, w as geometry_msgs/Quaternion orders them.
  Eigen::Vector4d quaternion() {
    Eigen::Vector4d xyzw;
    for (int i = 0; i < 4; ++i) xyzw[i] = next<double>();
    return xyzw;
  }
  std::array<double, 36> covariance() {
    std::array<double, 36> values{};
    for (double& value : values) value = next<double>();
    return values;
  }
  std::uint32_t bytesLeft() { return stream_.getLength(); }

 private:
  ros::serialization::IStream stream_;
};

// The heading of a quaternion (x, y, z, w) about z; none for a zero or non-finite quaternion.
// atan2 of two terms of the same degree in the quaternion: no need to normalise it first.
std::optional<double> yawOf(const Eigen::Vector4d& xyzw) {
  if (!xyzw.allFinite() || xyzw.squaredNorm() == 0.0) return std::nullopt;
  const double x = xyzw[0], y = xyzw[1], z = xyzw[2], w = xyzw[3];
  return std::atan2(2.0 * (w * z + x * y), w * w + x * x - y * y - z * z);
}

void readHeader(FieldReader& in, ObservedPeople& people) {
  in.skip(4);  // seq
  people.stamp = in.next<ros::Time>();
  people.frame_id = in.next<std::string>();
}

void skipHeader(FieldReader& in) {
  in.skip(4 + 8);   // seq, stamp
  in.skipString();  // frame_id
}

ObservedPerson readTrackedPerson(FieldReader& in) {
  ObservedPerson person;
  person.id = std::to_string(in.next<std::uint64_t>());
  person.occluded = in.next<bool>();
  in.skip(1 + 8 + 8);  // is_matched, detection_id, age
  person.position = in.vector3();
  const Eigen::Vector4d orientation = in.quaternion();
  const std::array<double, 36> pose_covariance = in.covariance();
  person.velocity = in.vector3();
  in.skip(kVector3Bytes + kCovarianceBytes);  // angular velocity, twist covariance
  if (pose_covariance[kYawVarianceIndex] < kUnknownVariance) person.yaw = yawOf(orientation);
  return person;
}

void readTrackedPersons(FieldReader& in, ObservedPeople& people) {
  readHeader(in, people);
  const std::uint32_t count = in.arrayLength(kTrackedPersonBytes, "tracked persons");
  for (std::uint32_t i = 0; i < count; ++i) people.people.push_back(readTrackedPerson(in));
}

// One agent, or none for pedsim's robot.
std::optional<ObservedPerson> readAgentState(FieldReader& in) {
  skipHeader(in);  // each agent has its own; the message's is the one used
  ObservedPerson person;
  person.id = std::to_string(in.next<std::uint64_t>());
  const auto type = in.next<std::uint16_t>();
  in.skipString();  // social_state
  person.position = in.vector3();
  person.yaw = yawOf(in.quaternion());
  person.velocity = in.vector3();
  in.skip(kVector3Bytes + kPedsimForcesBytes);  // angular velocity, forces
  if (type == kPedsimRobotType) return std::nullopt;
  return person;
}

void readAgentStates(FieldReader& in, ObservedPeople& people) {
  readHeader(in, people);
  const std::uint32_t count = in.arrayLength(kSmallestAgentStateBytes, "agent states");
  for (std::uint32_t i = 0; i < count; ++i) {
    if (std::optional<ObservedPerson> person = readAgentState(in)) people.people.push_back(std::move(*person));
  }
}

ObservedPerson readPerson(FieldReader& in) {
  ObservedPerson person;
  person.id = peopleNameId(in.next<std::string>());
  person.position = in.vector3();
  person.velocity = in.vector3();
  in.skip(8);        // reliability
  in.skipStrings();  // tagnames
  in.skipStrings();  // tags
  return person;
}

void readPeople(FieldReader& in, ObservedPeople& people) {
  readHeader(in, people);
  const std::uint32_t count = in.arrayLength(kSmallestPersonBytes, "people");
  for (std::uint32_t i = 0; i < count; ++i) people.people.push_back(readPerson(in));
}

bool isAsciiLetterOrDigit(unsigned char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// 32-bit FNV-1a: a fixed function of the bytes (std::hash may differ between builds).
std::uint32_t fnv1a(const std::string& text) {
  std::uint32_t hash = 2166136261u;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 16777619u;
  }
  return hash;
}

constexpr std::size_t kNameHashSuffixLength = 9;  // 'x' and eight hex digits

bool endsLikeNameHash(const std::string& id) {
  if (id.size() < kNameHashSuffixLength) return false;
  const std::size_t start = id.size() - kNameHashSuffixLength;
  if (id[start] != 'x') return false;
  for (std::size_t i = start + 1; i < id.size(); ++i) {
    const char c = id[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

// Writes the fields of a TrackedPersons message in order.
class FieldWriter {
 public:
  explicit FieldWriter(std::vector<std::uint8_t>& bytes)
      : stream_(bytes.data(), static_cast<std::uint32_t>(bytes.size())) {}
  template <typename Value>
  void next(const Value& value) {
    stream_.next(value);
  }
  void vector3(const Eigen::Vector3d& vector) {
    for (int i = 0; i < 3; ++i) next(vector[i]);
  }
  void quaternion(const Eigen::Vector4d& xyzw) {
    for (int i = 0; i < 4; ++i) next(xyzw[i]);
  }
  // A covariance with only its diagonal set.
  void diagonalCovariance(const std::array<double, 6>& diagonal) {
    for (std::size_t row = 0; row < 6; ++row) {
      for (std::size_t column = 0; column < 6; ++column) next(row == column ? diagonal[row] : 0.0);
    }
  }

 private:
  ros::serialization::OStream stream_;
};

void writeTrackedPerson(FieldWriter& out, const TrackedPersonOut& person) {
  out.next(person.track_id);
  out.next(person.is_occluded);
  // A person the player shows is one a detector would have seen: matched unless occluded. No
  // detections are published, so there is no detection id to give, nor a track age.
  out.next(!person.is_occluded);
  out.next(std::uint64_t{0});
  out.next(ros::Duration());
  out.vector3(person.position);
  const double half_yaw = person.yaw.value_or(0.0) / 2.0;
  out.quaternion(Eigen::Vector4d(0.0, 0.0, std::sin(half_yaw), std::cos(half_yaw)));
  const double yaw_variance = person.yaw ? kGroundTruthVariance : kUnknownVariance;
  // Upright people: no roll or pitch to report.
  out.diagonalCovariance({kGroundTruthVariance, kGroundTruthVariance, kGroundTruthVariance, kUnknownVariance,
                          kUnknownVariance, yaw_variance});
  out.vector3(person.velocity);
  out.vector3(Eigen::Vector3d::Zero());  // angular velocity: not known, variance 99999
  out.diagonalCovariance({kGroundTruthVariance, kGroundTruthVariance, kGroundTruthVariance, kUnknownVariance,
                          kUnknownVariance, kUnknownVariance});
}

}  // namespace

std::optional<PeopleLayout> peopleLayoutOf(const std::string& md5sum) {
  if (md5sum == kTrackedPersonsMd5) return PeopleLayout::kTrackedPersons;
  if (md5sum == kAgentStatesMd5) return PeopleLayout::kAgentStates;
  if (md5sum == kPeopleMd5) return PeopleLayout::kPeople;
  return std::nullopt;
}

std::string supportedPeopleTypes() {
  return std::string("spencer_tracking_msgs/TrackedPersons or pedsim_msgs/TrackedPersons (md5 ") + kTrackedPersonsMd5 +
         "), pedsim_msgs/AgentStates (md5 " + kAgentStatesMd5 + "), people_msgs/People (md5 " + kPeopleMd5 + ")";
}

ObservedPeople decodePeople(const topic_tools::ShapeShifter& message, const std::string& topic) {
  const std::optional<PeopleLayout> layout = peopleLayoutOf(message.getMD5Sum());
  if (!layout) {
    throw PeopleMessageError("topic '" + topic + "': its type " + message.getDataType() + " (md5 " +
                             message.getMD5Sum() + ") is not a people message this package reads; it reads " +
                             supportedPeopleTypes());
  }
  // ShapeShifter gives its bytes only by writing them to a stream.
  std::vector<std::uint8_t> bytes(message.size());
  ros::serialization::OStream copy(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  message.write(copy);

  const std::string what = std::string(layoutName(*layout)) + " message of " + std::to_string(bytes.size()) + " bytes";
  ObservedPeople people;
  FieldReader in(bytes);
  try {
    switch (*layout) {
      case PeopleLayout::kTrackedPersons:
        readTrackedPersons(in, people);
        break;
      case PeopleLayout::kAgentStates:
        readAgentStates(in, people);
        break;
      case PeopleLayout::kPeople:
        readPeople(in, people);
        break;
    }
  } catch (const ros::serialization::StreamOverrunException&) {
    throw PeopleMessageError("topic '" + topic + "': a " + what + " ends inside a field: truncated, or not " +
                             message.getDataType() + " as announced");
  } catch (const MalformedBytes& error) {
    throw PeopleMessageError("topic '" + topic + "': a " + what + " holds " + error.what());
  }
  if (in.bytesLeft() != 0) {
    throw PeopleMessageError("topic '" + topic + "': a " + what + " has " + std::to_string(in.bytesLeft()) +
                             " bytes after its last field: longer than its layout");
  }
  return people;
}

std::string peopleNameId(const std::string& name) {
  std::string id;
  for (unsigned char c : name) {
    if (isAsciiLetterOrDigit(c)) id += static_cast<char>(c);
  }
  // A name kept whole that already ends like a hash suffix gets one too: otherwise the name
  // "abx1234abcd" could be the id of "a-b".
  if (!id.empty() && id.size() == name.size() && !endsLikeNameHash(id)) return id;
  char suffix[kNameHashSuffixLength + 1];
  std::snprintf(suffix, sizeof suffix, "x%08x", static_cast<unsigned>(fnv1a(name)));
  return id + suffix;
}

topic_tools::ShapeShifter encodeTrackedPersons(const ros::Time& stamp, const std::string& frame_id,
                                               const std::vector<TrackedPersonOut>& persons) {
  const std::uint64_t length =
      kEmptyHeaderBytes + frame_id.size() + 4 + std::uint64_t{kTrackedPersonBytes} * persons.size();
  if (length > std::numeric_limits<std::uint32_t>::max()) {
    throw PeopleMessageError("a TrackedPersons message of " + std::to_string(persons.size()) +
                             " persons and a frame id of " + std::to_string(frame_id.size()) +
                             " characters exceeds ROS's 4 GiB message limit");
  }
  std::vector<std::uint8_t> bytes(length);
  FieldWriter out(bytes);
  out.next(std::uint32_t{0});  // seq: not counted here, as ROS leaves it to the publisher
  out.next(stamp);
  out.next(frame_id);
  out.next(static_cast<std::uint32_t>(persons.size()));
  for (const TrackedPersonOut& person : persons) writeTrackedPerson(out, person);

  topic_tools::ShapeShifter message;
  message.morph(kTrackedPersonsMd5, kTrackedPersonsType, kTrackedPersonsDefinition, "");
  ros::serialization::IStream filled(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  message.read(filled);
  return message;
}

}  // namespace dressed_human
