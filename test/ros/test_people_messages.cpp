// The people messages of other packages (src/node/people_messages.h), read from bytes that genpy
// serialized (test/data/people_messages/, made by scripts/make_people_message_fixtures.py) and
// written by encodeTrackedPersons. Needs roscpp's and topic_tools' libraries, not a ROS master.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dressed_human/core/skeleton/skeleton.h"
#include "node/people_messages.h"

namespace dressed_human {
namespace {

constexpr char kTopic[] = "/tracked_people_topic";

struct Fixture {
  std::string type;
  std::string md5sum;
  ros::Time stamp;
  std::string frame_id;
  std::vector<ObservedPerson> people;  // what decodePeople should make of the bytes
  std::vector<std::uint8_t> bytes;
};

std::vector<std::uint8_t> bytesFromHex(std::string hex) {
  hex.erase(std::remove_if(hex.begin(), hex.end(), [](unsigned char c) { return std::isspace(c) != 0; }), hex.end());
  if (hex.size() % 2 != 0) throw std::runtime_error("odd number of hex digits");
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    bytes.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
  }
  return bytes;
}

Eigen::Vector3d vector3(const YAML::Node& node) {
  return Eigen::Vector3d(node[0].as<double>(), node[1].as<double>(), node[2].as<double>());
}

Fixture loadFixture(const std::string& name) {
  const YAML::Node file =
      YAML::LoadFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/test/data/people_messages/" + name + ".yaml");
  Fixture fixture;
  fixture.type = file["type"].as<std::string>();
  fixture.md5sum = file["md5sum"].as<std::string>();
  fixture.stamp = ros::Time(file["stamp"]["secs"].as<std::uint32_t>(), file["stamp"]["nsecs"].as<std::uint32_t>());
  fixture.frame_id = file["frame_id"].as<std::string>();
  for (const YAML::Node& entry : file["people"]) {
    ObservedPerson person;
    person.id = entry["id"].as<std::string>();
    person.position = vector3(entry["position"]);
    person.velocity = vector3(entry["velocity"]);
    if (!entry["yaw"].IsNull()) person.yaw = entry["yaw"].as<double>();
    person.occluded = entry["occluded"].as<bool>();
    fixture.people.push_back(person);
  }
  fixture.bytes = bytesFromHex(file["bytes"].as<std::string>());
  return fixture;
}

// A received message as roscpp hands it to a ShapeShifter subscriber: the connection header's
// md5sum and type, then the bytes.
topic_tools::ShapeShifter received(const std::string& md5sum, const std::string& type,
                                   std::vector<std::uint8_t> bytes) {
  topic_tools::ShapeShifter message;
  message.morph(md5sum, type, "", "");
  ros::serialization::IStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  message.read(stream);
  return message;
}

topic_tools::ShapeShifter received(const Fixture& fixture) {
  return received(fixture.md5sum, fixture.type, fixture.bytes);
}

std::vector<std::uint8_t> bytesOf(const topic_tools::ShapeShifter& message) {
  std::vector<std::uint8_t> bytes(message.size());
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  message.write(stream);
  return bytes;
}

void expectSamePeople(const std::vector<ObservedPerson>& expected, const std::vector<ObservedPerson>& decoded) {
  ASSERT_EQ(decoded.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("person " + std::to_string(i) + " (" + expected[i].id + ")");
    EXPECT_EQ(decoded[i].id, expected[i].id);
    EXPECT_TRUE(isHumanId(decoded[i].id)) << decoded[i].id;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_DOUBLE_EQ(decoded[i].position[axis], expected[i].position[axis]) << "axis " << axis;
      EXPECT_DOUBLE_EQ(decoded[i].velocity[axis], expected[i].velocity[axis]) << "axis " << axis;
    }
    ASSERT_EQ(decoded[i].yaw.has_value(), expected[i].yaw.has_value());
    if (expected[i].yaw) {
      EXPECT_NEAR(*decoded[i].yaw, *expected[i].yaw, 1e-12);
    }
    EXPECT_EQ(decoded[i].occluded, expected[i].occluded);
  }
}

void expectDecodedAsFixtureSays(const std::string& name) {
  SCOPED_TRACE(name);
  const Fixture fixture = loadFixture(name);
  const ObservedPeople decoded = decodePeople(received(fixture), kTopic);
  EXPECT_EQ(decoded.stamp, fixture.stamp);
  EXPECT_EQ(decoded.frame_id, fixture.frame_id);
  expectSamePeople(fixture.people, decoded.people);
}

const std::vector<std::string> kFixtures = {"tracked_persons", "tracked_persons_tracker", "agent_states", "people"};

TEST(PeopleMessages, TrackedPersonsAsEncodeWritesThemAreDecodedFieldByField) {
  expectDecodedAsFixtureSays("tracked_persons");
}

TEST(PeopleMessages, TrackedPersonsAsATrackerWritesThemAreDecodedFieldByField) {
  expectDecodedAsFixtureSays("tracked_persons_tracker");
}

TEST(PeopleMessages, AgentStatesAreDecodedFieldByFieldWithoutTheRobot) { expectDecodedAsFixtureSays("agent_states"); }

TEST(PeopleMessages, PeopleAreDecodedFieldByFieldWithTheirNamesAsIds) { expectDecodedAsFixtureSays("people"); }

TEST(PeopleMessages, PedsimsTrackedPersonsIsReadAsSpencers) {
  const Fixture fixture = loadFixture("tracked_persons");
  const ObservedPeople decoded =
      decodePeople(received(fixture.md5sum, "pedsim_msgs/TrackedPersons", fixture.bytes), kTopic);
  expectSamePeople(fixture.people, decoded.people);
}

TEST(PeopleMessages, EachFixtureMd5IsALayoutAndAnotherIsNone) {
  EXPECT_EQ(peopleLayoutOf(loadFixture("tracked_persons").md5sum), PeopleLayout::kTrackedPersons);
  EXPECT_EQ(peopleLayoutOf(loadFixture("agent_states").md5sum), PeopleLayout::kAgentStates);
  EXPECT_EQ(peopleLayoutOf(loadFixture("people").md5sum), PeopleLayout::kPeople);
  EXPECT_FALSE(peopleLayoutOf("992ce8a1687cec8c8bd883ec73ca41d1"));  // std_msgs/String
  EXPECT_FALSE(peopleLayoutOf("*"));
}

TEST(PeopleMessages, AnUnknownLayoutIsRefusedNamingTopicTypeAndTheSupportedOnes) {
  const std::vector<std::uint8_t> bytes = {2, 0, 0, 0, 'h', 'i'};
  try {
    decodePeople(received("992ce8a1687cec8c8bd883ec73ca41d1", "std_msgs/String", bytes), kTopic);
    FAIL() << "a std_msgs/String was decoded as people";
  } catch (const PeopleMessageError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(kTopic), std::string::npos) << message;
    EXPECT_NE(message.find("std_msgs/String"), std::string::npos) << message;
    EXPECT_NE(message.find(supportedPeopleTypes()), std::string::npos) << message;
  }
  for (const char* type : {"spencer_tracking_msgs/TrackedPersons", "pedsim_msgs/TrackedPersons",
                           "pedsim_msgs/AgentStates", "people_msgs/People"}) {
    EXPECT_NE(supportedPeopleTypes().find(type), std::string::npos) << type;
  }
}

// The error for bytes that do not hold their layout, or none if they were decoded.
std::string decodingError(const Fixture& fixture, const std::vector<std::uint8_t>& bytes) {
  try {
    decodePeople(received(fixture.md5sum, fixture.type, bytes), kTopic);
  } catch (const PeopleMessageError& error) {
    return error.what();
  }
  return "";
}

TEST(PeopleMessages, EveryTruncationOfEveryFixtureIsRefusedNamingTheTopic) {
  for (const std::string& name : kFixtures) {
    const Fixture fixture = loadFixture(name);
    for (std::size_t length = 0; length < fixture.bytes.size(); ++length) {
      const std::vector<std::uint8_t> cut(fixture.bytes.begin(),
                                          fixture.bytes.begin() + static_cast<std::ptrdiff_t>(length));
      const std::string error = decodingError(fixture, cut);
      ASSERT_NE(error.find(kTopic), std::string::npos) << name << " cut to " << length << " bytes: '" << error << "'";
    }
  }
}

TEST(PeopleMessages, OneByteMoreThanTheLayoutIsRefusedNamingTheTopic) {
  for (const std::string& name : kFixtures) {
    Fixture fixture = loadFixture(name);
    fixture.bytes.push_back(0);
    const std::string error = decodingError(fixture, fixture.bytes);
    EXPECT_NE(error.find(kTopic), std::string::npos) << name << ": '" << error << "'";
    EXPECT_NE(error.find("1 bytes after its last field"), std::string::npos) << name << ": '" << error << "'";
  }
}

TEST(PeopleMessages, AnArrayCountTheBytesCannotHoldIsRefusedAtOnce) {
  Fixture fixture = loadFixture("tracked_persons");
  // The tracks' count follows the header: seq, stamp, frame_id (its length, then its characters).
  const std::size_t count_offset = 4 + 8 + 4 + fixture.frame_id.size();
  for (std::size_t i = 0; i < 4; ++i) fixture.bytes[count_offset + i] = 0xff;
  const std::string error = decodingError(fixture, fixture.bytes);
  EXPECT_NE(error.find(kTopic), std::string::npos) << error;
  EXPECT_NE(error.find("an array of 4294967295 tracked persons"), std::string::npos) << error;
}

std::vector<TrackedPersonOut> trackedPersonsOf(const Fixture& fixture) {
  std::vector<TrackedPersonOut> persons;
  for (const ObservedPerson& person : fixture.people) {
    TrackedPersonOut out;
    out.track_id = std::stoull(person.id);
    out.is_occluded = person.occluded;
    out.position = person.position;
    out.velocity = person.velocity;
    out.yaw = person.yaw;
    persons.push_back(out);
  }
  return persons;
}

TEST(PeopleMessages, EncodedTrackedPersonsAreByteForByteGenpys) {
  const Fixture fixture = loadFixture("tracked_persons");
  const topic_tools::ShapeShifter encoded =
      encodeTrackedPersons(fixture.stamp, fixture.frame_id, trackedPersonsOf(fixture));
  EXPECT_EQ(encoded.getMD5Sum(), fixture.md5sum);
  EXPECT_EQ(encoded.getDataType(), "spencer_tracking_msgs/TrackedPersons");
  // Its text is checked against genmsg's by test_people_message_layouts.py.
  EXPECT_EQ(encoded.getMessageDefinition().rfind("# Message with all currently tracked persons", 0), 0u);
  EXPECT_EQ(bytesOf(encoded), fixture.bytes);
}

TEST(PeopleMessages, EncodedTrackedPersonsDecodeToWhatWasEncoded) {
  std::vector<TrackedPersonOut> persons(2);
  persons[0].track_id = 17;
  persons[0].position = Eigen::Vector3d(0.1, -0.2, 0.3);
  persons[0].velocity = Eigen::Vector3d(1.1, 1.2, 0.0);
  persons[0].yaw = 3.1;
  persons[1].track_id = 0;
  persons[1].is_occluded = true;
  persons[1].position = Eigen::Vector3d(-9.0, 8.5, 0.0);
  const ros::Time stamp(12, 345);
  const ObservedPeople decoded = decodePeople(encodeTrackedPersons(stamp, "world", persons), kTopic);
  EXPECT_EQ(decoded.stamp, stamp);
  EXPECT_EQ(decoded.frame_id, "world");
  ASSERT_EQ(decoded.people.size(), persons.size());
  for (std::size_t i = 0; i < persons.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(decoded.people[i].id, std::to_string(persons[i].track_id));
    EXPECT_EQ(decoded.people[i].position, persons[i].position);
    EXPECT_EQ(decoded.people[i].velocity, persons[i].velocity);
    EXPECT_EQ(decoded.people[i].occluded, persons[i].is_occluded);
    ASSERT_EQ(decoded.people[i].yaw.has_value(), persons[i].yaw.has_value());
    if (persons[i].yaw) {
      EXPECT_NEAR(*decoded.people[i].yaw, *persons[i].yaw, 1e-12);
    }
  }
  EXPECT_TRUE(decodePeople(encodeTrackedPersons(stamp, "", {}), kTopic).people.empty());
}

TEST(PeopleMessages, ANameIdIsTheSameEveryRunAndMadeOfLettersAndDigits) {
  // The value the fixture script computed (its own FNV-1a): the same in every run and build.
  EXPECT_EQ(peopleNameId("bob-2"), "bob2xf620616b");
  EXPECT_EQ(peopleNameId("bob-2"), peopleNameId("bob-2"));
  for (const std::string name : {"alice", "a-b", "ab", "", "---", "Person 7", "caf\xc3\xa9", "abx1234abcd"}) {
    EXPECT_TRUE(isHumanId(peopleNameId(name))) << "'" << name << "' -> '" << peopleNameId(name) << "'";
  }
}

TEST(PeopleMessages, NamesThatDifferOnlyInOtherCharactersStayTwoPeople) {
  EXPECT_EQ(peopleNameId("ab"), "ab");
  EXPECT_NE(peopleNameId("a-b"), peopleNameId("ab"));
  EXPECT_NE(peopleNameId("a-b"), peopleNameId("a_b"));
  EXPECT_NE(peopleNameId(""), peopleNameId("-"));
  EXPECT_EQ(peopleNameId("a-b").rfind("ab", 0), 0u) << "the letters kept, in order";
  // A name already shaped like a sanitised one is not taken whole, or it could be another's id.
  const std::string sanitised = peopleNameId("a-b");
  EXPECT_NE(peopleNameId(sanitised), sanitised);
}

}  // namespace
}  // namespace dressed_human
