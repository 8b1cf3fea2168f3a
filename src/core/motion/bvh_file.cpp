#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/io/text_file.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace dressed_human {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
// Guards against hostile input (the parser is fuzzed): no real skeleton comes near these.
constexpr std::size_t kMaxJoints = 4096;
constexpr std::size_t kMaxDepth = 256;

struct Token {
  std::string text;
  std::size_t line;
};

// Splits on white space, remembering the line of every token for error messages.
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> tokens;
  std::size_t line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != '\r' && text[end] != '\n' &&
           text[end] != '\f' && text[end] != '\v') {
      ++end;
    }
    tokens.push_back({text.substr(i, end - i), line});
    i = end;
  }
  return tokens;
}

class BvhReader {
 public:
  BvhReader(const std::string& text, std::string source) : tokens_(tokenize(text)), source_(std::move(source)) {}

  BvhClip read() {
    expect("HIERARCHY");
    const Token& root = next("ROOT");
    if (root.text != "ROOT") fail(root, "expected ROOT, got '" + root.text + "'");
    readHierarchy();
    readMotion();
    return std::move(clip_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& message) const {
    throw BvhError(source_ + ":" + std::to_string(line) + ": " + message);
  }
  [[noreturn]] void fail(const Token& token, const std::string& message) const { fail(token.line, message); }

  std::size_t lastLine() const { return tokens_.empty() ? 1 : tokens_.back().line; }

  const Token& next(const std::string& what) {
    if (at_ >= tokens_.size()) fail(lastLine(), "unexpected end of file, expected " + what);
    return tokens_[at_++];
  }

  void expect(const std::string& word) {
    const Token& token = next("'" + word + "'");
    if (token.text != word) fail(token, "expected '" + word + "', got '" + token.text + "'");
  }

  double number(const std::string& what) {
    const Token& token = next(what);
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.text.c_str(), &end);
    if (end == token.text.c_str() || *end != '\0')
      fail(token, "expected a number (" + what + "), got '" + token.text + "'");
    if (!std::isfinite(value)) fail(token, what + " must be a finite number, got '" + token.text + "'");
    return value;
  }

  std::size_t count(const std::string& what, std::size_t maximum) {
    const Token& token = next(what);
    std::size_t value = 0;
    if (token.text.empty()) fail(token, "expected " + what);
    for (const char c : token.text) {
      if (c < '0' || c > '9')
        fail(token, "expected a non-negative whole number (" + what + "), got '" + token.text + "'");
      value = value * 10 + static_cast<std::size_t>(c - '0');
      if (value > maximum)
        fail(token, what + " " + token.text + " is more than the supported " + std::to_string(maximum));
    }
    return value;
  }

  BvhChannel channel() {
    const Token& token = next("a channel name");
    static const std::array<const char*, 6> names = {"Xposition", "Yposition", "Zposition",
                                                     "Xrotation", "Yrotation", "Zrotation"};
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (token.text == names[i]) return static_cast<BvhChannel>(i);
    }
    fail(token, "unknown channel '" + token.text + "' (expected X/Y/Z position or rotation)");
  }

  Eigen::Vector3d offset() {
    expect("OFFSET");
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = number("OFFSET component");
    return v;
  }

  // Iterative (not recursive) so that deeply nested hostile input cannot overflow the stack.
  void readHierarchy() {
    std::vector<int> open;  // joints whose '}' is pending; -2 marks an End Site block
    startJoint(-1);
    open.push_back(0);
    while (!open.empty()) {
      const Token& token = next("JOINT, End Site or '}'");
      if (token.text == "}") {
        open.pop_back();
        continue;
      }
      if (open.back() == -2) fail(token, "an End Site block holds only its OFFSET, got '" + token.text + "'");
      if (open.size() > kMaxDepth) fail(token, "the hierarchy is nested deeper than " + std::to_string(kMaxDepth));
      if (token.text == "JOINT") {
        open.push_back(startJoint(open.back()));
      } else if (token.text == "End") {
        expect("Site");
        expect("{");
        clip_.joints[static_cast<std::size_t>(open.back())].end_sites.push_back(offset());
        open.push_back(-2);
      } else {
        fail(token, "expected JOINT, End Site or '}', got '" + token.text + "'");
      }
    }
  }

  int startJoint(int parent) {
    if (clip_.joints.size() >= kMaxJoints)
      fail(tokens_[at_ - 1], "more than " + std::to_string(kMaxJoints) + " joints");
    BvhJoint joint;
    const Token& name = next("a joint name");
    if (name.text == "{") fail(name, "the joint has no name");
    joint.name = name.text;
    if (clip_.findJoint(joint.name) >= 0) fail(name, "joint name '" + joint.name + "' appears twice");
    joint.parent = parent;
    expect("{");
    joint.offset = offset();
    expect("CHANNELS");
    const std::size_t channels = count("channel count", 6);
    for (std::size_t c = 0; c < channels; ++c) {
      const BvhChannel kind = channel();
      for (const BvhChannel other : joint.channels) {
        if (other == kind) fail(tokens_[at_ - 1], "joint '" + joint.name + "' lists the same channel twice");
      }
      joint.channels.push_back(kind);
    }
    joint.first_channel = clip_.channel_count;
    clip_.channel_count += channels;
    const int index = static_cast<int>(clip_.joints.size());
    if (parent >= 0) clip_.joints[static_cast<std::size_t>(parent)].children.push_back(index);
    clip_.joints.push_back(std::move(joint));
    return index;
  }

  void readMotion() {
    expect("MOTION");
    expect("Frames:");
    const std::size_t frames = count("frame count", 100000000);
    expect("Frame");
    expect("Time:");
    const Token& time_token = tokens_[at_ < tokens_.size() ? at_ : tokens_.size() - 1];
    clip_.frame_time = number("Frame Time");
    if (!(clip_.frame_time > 0.0)) fail(time_token, "Frame Time must be > 0 seconds");
    const std::size_t available = tokens_.size() - at_;
    const std::size_t needed_line = at_ < tokens_.size() ? tokens_[at_].line : lastLine();
    if (clip_.channel_count == 0) {
      fail(needed_line, "the hierarchy has no channels: there is no motion to read");
    }
    if (available / clip_.channel_count < frames) {
      fail(needed_line, "'Frames: " + std::to_string(frames) + "' with " + std::to_string(clip_.channel_count) +
                            " channels needs " + std::to_string(frames) + " x " + std::to_string(clip_.channel_count) +
                            " numbers, the file holds " + std::to_string(available));
    }
    clip_.frames.assign(frames, std::vector<double>(clip_.channel_count, 0.0));
    for (std::size_t f = 0; f < frames; ++f) {
      for (std::size_t c = 0; c < clip_.channel_count; ++c) {
        clip_.frames[f][c] = number("frame " + std::to_string(f + 1) + " channel " + std::to_string(c + 1));
      }
    }
    if (at_ < tokens_.size()) {
      fail(tokens_[at_], "more numbers than 'Frames: " + std::to_string(frames) + "' x " +
                             std::to_string(clip_.channel_count) + " channels");
    }
  }

  std::vector<Token> tokens_;
  std::size_t at_ = 0;
  std::string source_;
  BvhClip clip_;
};

Eigen::Matrix3d axisRotation(BvhChannel channel, double degrees) {
  const int axis = static_cast<int>(channel) - static_cast<int>(BvhChannel::kXrotation);
  return Eigen::AngleAxisd(degrees * kDegree, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

bool isRotation(BvhChannel channel) { return static_cast<int>(channel) >= static_cast<int>(BvhChannel::kXrotation); }

}  // namespace

int BvhClip::findJoint(const std::string& name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Matrix3d BvhClip::localRotation(std::size_t frame, std::size_t joint) const {
  const BvhJoint& j = joints.at(joint);
  const std::vector<double>& values = frames.at(frame);
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  for (std::size_t c = 0; c < j.channels.size(); ++c) {
    if (isRotation(j.channels[c])) rotation = rotation * axisRotation(j.channels[c], values[j.first_channel + c]);
  }
  return rotation;
}

Eigen::Vector3d BvhClip::localTranslation(std::size_t frame, std::size_t joint) const {
  const BvhJoint& j = joints.at(joint);
  const std::vector<double>& values = frames.at(frame);
  // Position channels replace the offset, as Blender's importer reads them: rigs that key every
  // joint's position (Bandai-Namco's) repeat the offset there, and roots whose offset is their
  // first frame's place (LAFAN1's) would otherwise stand twice as far off.
  Eigen::Vector3d translation = j.offset;
  for (std::size_t c = 0; c < j.channels.size(); ++c) {
    if (!isRotation(j.channels[c])) translation[static_cast<int>(j.channels[c])] = values[j.first_channel + c];
  }
  return translation;
}

namespace {

BvhPose chainPose(const BvhClip& clip, const std::vector<Eigen::Matrix3d>& local_rotation,
                  const std::vector<Eigen::Vector3d>& local_translation) {
  BvhPose pose;
  pose.rotation.resize(clip.joints.size());
  pose.position.resize(clip.joints.size());
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const int parent = clip.joints[j].parent;
    if (parent < 0) {
      pose.rotation[j] = local_rotation[j];
      pose.position[j] = local_translation[j];
    } else {
      const auto p = static_cast<std::size_t>(parent);
      pose.rotation[j] = pose.rotation[p] * local_rotation[j];
      pose.position[j] = pose.position[p] + pose.rotation[p] * local_translation[j];
    }
  }
  return pose;
}

}  // namespace

BvhPose bvhForwardKinematics(const BvhClip& clip, std::size_t frame) {
  std::vector<Eigen::Matrix3d> rotation(clip.joints.size());
  std::vector<Eigen::Vector3d> translation(clip.joints.size());
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    rotation[j] = clip.localRotation(frame, j);
    translation[j] = clip.localTranslation(frame, j);
  }
  return chainPose(clip, rotation, translation);
}

BvhPose bvhRestPose(const BvhClip& clip) {
  std::vector<Eigen::Matrix3d> rotation(clip.joints.size(), Eigen::Matrix3d::Identity());
  std::vector<Eigen::Vector3d> translation(clip.joints.size());
  for (std::size_t j = 0; j < clip.joints.size(); ++j) translation[j] = clip.joints[j].offset;
  return chainPose(clip, rotation, translation);
}

BvhPoint bvhFarthestPointBelow(const BvhClip& clip, const BvhPose& pose, std::size_t joint) {
  BvhPoint farthest{joint, -1};
  double distance = 0.0;
  const auto consider = [&](const BvhPoint& point) {
    const double d = (bvhPointPosition(clip, pose, point) - pose.position[joint]).norm();
    if (d > distance) {
      distance = d;
      farthest = point;
    }
  };
  for (const std::size_t j : bvhSubtree(clip, joint)) {
    consider({j, -1});
    for (std::size_t e = 0; e < clip.joints[j].end_sites.size(); ++e) consider({j, static_cast<int>(e)});
  }
  return farthest;
}

Eigen::Vector3d bvhPointPosition(const BvhClip& clip, const BvhPose& pose, const BvhPoint& point) {
  const Eigen::Vector3d& at = pose.position[point.joint];
  return point.end_site < 0
             ? at
             : Eigen::Vector3d(at + pose.rotation[point.joint] *
                                        clip.joints[point.joint].end_sites[static_cast<std::size_t>(point.end_site)]);
}

Eigen::Vector3d bvhFarthestBelow(const BvhClip& clip, const BvhPose& pose, std::size_t joint) {
  return bvhPointPosition(clip, pose, bvhFarthestPointBelow(clip, pose, joint)) - pose.position[joint];
}

std::vector<std::size_t> bvhSubtree(const BvhClip& clip, std::size_t joint) {
  std::vector<std::size_t> subtree;
  std::vector<std::size_t> stack = {joint};
  while (!stack.empty()) {
    subtree.push_back(stack.back());
    stack.pop_back();
    for (const int child : clip.joints[subtree.back()].children) stack.push_back(static_cast<std::size_t>(child));
  }
  return subtree;
}

BvhClip parseBvh(const std::string& text, const std::string& source_name) {
  return BvhReader(text, source_name).read();
}

BvhClip loadBvhFile(const std::string& path) {
  return parseBvh(readWholeFileOrThrow<BvhError>(path, "the BVH file"), path);
}

}  // namespace dressed_human
