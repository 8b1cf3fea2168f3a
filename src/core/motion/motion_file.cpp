#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/io/text_file.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

#include "dressed_human/core/io/yaml_reader.h"
#include "dressed_human/core/skeleton/body_shape_yaml.h"

namespace dressed_human {
namespace {

using Reader = YamlReader<MotionError>;

FourierSeries readSeries(const Reader& reader, const YAML::Node& node, const std::string& key, double default_period) {
  reader.requireMap(node, key);
  reader.rejectUnknownKeys(node, key, {"a0", "a", "b", "period", "phase", "rms_residual"});
  FourierSeries s;
  s.period = default_period;
  s.a0 = reader.number(reader.require(node, "a0", key), key + ".a0");
  // a_1..a_m and b_1..b_m: messages number them as the equation does.
  if (node["a"]) s.a = reader.numbers(node["a"], key + ".a", 0, "", 1);
  if (node["b"]) s.b = reader.numbers(node["b"], key + ".b", 0, "", 1);
  if (s.a.size() != s.b.size()) {
    reader.fail(node, key,
                "wrong coefficient counts: " + std::to_string(s.a.size()) + " in a but " + std::to_string(s.b.size()) +
                    " in b; both must list a_1..a_m and b_1..b_m");
  }
  if (node["period"]) {
    s.period = reader.number(node["period"], key + ".period");
    if (s.period <= 0.0) reader.fail(node["period"], key + ".period", "must be > 0 seconds");
  }
  if (node["phase"]) s.phase = reader.number(node["phase"], key + ".phase");
  if (node["rms_residual"] && reader.number(node["rms_residual"], key + ".rms_residual") < 0.0) {
    reader.fail(node["rms_residual"], key + ".rms_residual", "must be >= 0");
  }
  return s;
}

template <std::size_t N>
std::set<std::string> namesOf(const std::array<const char*, N>& names) {
  return std::set<std::string>(names.begin(), names.end());
}

}  // namespace

Motion parseMotionYaml(const std::string& yaml_text, const std::string& source_name) {
  const Reader reader(source_name);
  const YAML::Node document = reader.load(yaml_text, "the motion file");
  reader.rejectUnknownKeys(document, "", {"name", "period", "joints", "root", "body_shape"});

  Motion motion;
  if (document["name"]) {
    motion.name = reader.text(document["name"], "name");
  }
  const YAML::Node period = reader.require(document, "period", "");
  motion.period = reader.number(period, "period");
  if (motion.period <= 0.0) reader.fail(period, "period", "must be > 0 seconds, got " + period.Scalar());
  if (const YAML::Node shape = document["body_shape"]) {
    motion.body_shape.emplace();
    readBodyShapeYaml(reader, shape, "body_shape", *motion.body_shape);
  }

  const YAML::Node joints = reader.require(document, "joints", "");
  reader.requireMap(joints, "joints");
  reader.rejectUnknownKeys(joints, "joints", namesOf(humanJointNames()));
  for (std::size_t j = 0; j < kJointCount; ++j) {
    const std::string joint_key = std::string("joints.") + humanJointNames()[j];
    const YAML::Node joint = reader.require(joints, humanJointNames()[j], "joints");
    reader.requireMap(joint, joint_key);
    reader.rejectUnknownKeys(joint, joint_key, namesOf(kDofNames));
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
      const std::string dof_key = joint_key + "." + kDofNames[d];
      motion.dofs[j * kDofsPerJoint + d] =
          readSeries(reader, reader.require(joint, kDofNames[d], joint_key), dof_key, motion.period);
    }
  }

  const YAML::Node root = reader.require(document, "root", "");
  reader.requireMap(root, "root");
  reader.rejectUnknownKeys(root, "root", {"forward_speed", "translation", "rotation"});
  motion.root.forward_speed = reader.number(reader.require(root, "forward_speed", "root"), "root.forward_speed");
  const YAML::Node translation = reader.require(root, "translation", "root");
  reader.requireMap(translation, "root.translation");
  reader.rejectUnknownKeys(translation, "root.translation", namesOf(kRootTranslationNames));
  const YAML::Node rotation = reader.require(root, "rotation", "root");
  reader.requireMap(rotation, "root.rotation");
  reader.rejectUnknownKeys(rotation, "root.rotation", namesOf(kRootRotationNames));
  for (std::size_t k = 0; k < 3; ++k) {
    motion.root.translation[k] =
        readSeries(reader, reader.require(translation, kRootTranslationNames[k], "root.translation"),
                   std::string("root.translation.") + kRootTranslationNames[k], motion.period);
    motion.root.rotation[k] = readSeries(reader, reader.require(rotation, kRootRotationNames[k], "root.rotation"),
                                         std::string("root.rotation.") + kRootRotationNames[k], motion.period);
  }
  try {
    motion.validate();
  } catch (const MotionError& error) {
    throw MotionError(source_name + ": " + error.what());
  }
  return motion;
}

Motion loadMotionFile(const std::string& path) {
  return parseMotionYaml(readWholeFileOrThrow<MotionError>(path, "the motion file"), path);
}

namespace {

void writeList(std::ostream& out, const std::vector<double>& values) {
  out << '[';
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  out << ']';
}

void writeSeries(std::ostream& out, const FourierSeries& s, double default_period, const std::string& note,
                 const double* rms_residual) {
  out << "{a0: " << s.a0;
  if (s.order() > 0) {
    out << ", a: ";
    writeList(out, s.a);
    out << ", b: ";
    writeList(out, s.b);
  }
  if (s.period != default_period) out << ", period: " << s.period;
  if (s.phase != 0.0) out << ", phase: " << s.phase;
  if (rms_residual) out << ", rms_residual: " << *rms_residual;
  out << '}';
  if (!note.empty()) out << "  # " << note;
  out << '\n';
}

}  // namespace

void writeMotionYaml(const Motion& motion, std::ostream& out, const std::string& header_comment,
                     const std::map<std::string, std::string>& notes,
                     const std::map<std::string, double>& rms_residuals) {
  motion.validate();
  const auto note = [&](std::size_t i) {
    const auto found = notes.find(motion.seriesName(i));
    return found == notes.end() ? std::string() : found->second;
  };
  const auto residual = [&](std::size_t i) -> const double* {
    const auto found = rms_residuals.find(motion.seriesName(i));
    return found == rms_residuals.end() ? nullptr : &found->second;
  };
  std::ostringstream text;
  text << std::setprecision(std::numeric_limits<double>::max_digits10);
  std::istringstream header(header_comment);
  for (std::string line; std::getline(header, line);) text << "# " << line << '\n';
  if (!motion.name.empty()) text << "name: " << motion.name << '\n';
  text << "period: " << motion.period << '\n' << "joints:\n";
  for (std::size_t j = 0; j < kJointCount; ++j) {
    text << "  " << humanJointNames()[j] << ":\n";
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
      text << "    " << kDofNames[d] << ": ";
      writeSeries(text, motion.dofs[j * kDofsPerJoint + d], motion.period, note(j * kDofsPerJoint + d),
                  residual(j * kDofsPerJoint + d));
    }
  }
  text << "root:\n  forward_speed: " << motion.root.forward_speed << "\n  translation:\n";
  for (std::size_t k = 0; k < 3; ++k) {
    text << "    " << kRootTranslationNames[k] << ": ";
    writeSeries(text, motion.root.translation[k], motion.period, note(kDofCount + k), residual(kDofCount + k));
  }
  text << "  rotation:\n";
  for (std::size_t k = 0; k < 3; ++k) {
    text << "    " << kRootRotationNames[k] << ": ";
    writeSeries(text, motion.root.rotation[k], motion.period, note(kDofCount + 3 + k), residual(kDofCount + 3 + k));
  }
  if (motion.body_shape) {
    text << "body_shape:  # the person's proportions (Eq. 5 [a, b, c] per bone, then the joint's offset in metres if "
            "any):\n"
         << "             # robot_description must carry them (human_urdf)\n";
    text << std::setprecision(6);
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      const Eigen::Vector3d& abc = motion.body_shape->scale[b];
      const Eigen::Vector3d& offset = motion.body_shape->offset[b];
      text << "  " << humanBoneLayout()[b].name << ": [" << abc.x() << ", " << abc.y() << ", " << abc.z();
      if (!offset.isZero(0.0)) text << ", " << offset.x() << ", " << offset.y() << ", " << offset.z();
      text << "]\n";
    }
  }
  out << text.str();
}

}  // namespace dressed_human
