#include "dressed_human/core/skeleton/urdf_body_shape.h"

#include <cmath>
#include <cstdio>
#include <map>

#include <tinyxml2.h>

namespace dressed_human {
namespace {

constexpr const char* kShapeElement = "dressed_human_body_shape";
constexpr std::array<const char*, 3> kFactorNames = {"a", "b", "c"};

std::string numberText(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", value);
  return text;
}

std::string vectorText(const Eigen::Vector3d& v) {
  return numberText(v.x()) + " " + numberText(v.y()) + " " + numberText(v.z());
}

Eigen::Vector3d parseVector(const char* text) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  if (text) std::sscanf(text, "%lf %lf %lf", &v.x(), &v.y(), &v.z());
  return v;
}

void parse(tinyxml2::XMLDocument& document, const std::string& urdf_xml) {
  if (document.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS ||
      !document.FirstChildElement("robot")) {
    throw SkeletonError(std::string("the URDF is not valid XML with a <robot> element: ") +
                        (document.ErrorStr() ? document.ErrorStr() : "no <robot>"));
  }
}

// Bone index by URDF link name (with the suffix the root link "body<suffix>" gives).
std::map<std::string, std::size_t> boneLinks(const tinyxml2::XMLElement& robot, std::string& suffix) {
  for (const tinyxml2::XMLElement* link = robot.FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    const std::string name = link->Attribute("name") ? link->Attribute("name") : "";
    if (name == "body" || name.rfind("body_", 0) == 0) suffix = name.substr(4);
  }
  std::map<std::string, std::size_t> links;
  const auto& layout = humanBoneLayout();
  for (std::size_t b = 0; b < kBoneCount; ++b) links[layout[b].name + suffix] = b;
  return links;
}

}  // namespace

bool BodyShape::isIdentity() const {
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    if (scale[b] != Eigen::Vector3d::Ones() || !offset[b].isZero(0.0)) return false;
  }
  return true;
}

BodyShape BodyShape::appliedOn(const BodyShape& base) const {
  BodyShape combined;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    combined.scale[b] = scale[b].cwiseProduct(base.scale[b]);
    combined.offset[b] = offset[b] + base.offset[b];
  }
  return combined;
}

BodyShape urdfBodyShape(const std::string& urdf_xml) {
  tinyxml2::XMLDocument document;
  parse(document, urdf_xml);
  BodyShape shape;
  const tinyxml2::XMLElement* record = document.FirstChildElement("robot")->FirstChildElement(kShapeElement);
  if (!record) return shape;
  const auto& layout = humanBoneLayout();
  std::array<bool, kBoneCount> seen{};
  for (const tinyxml2::XMLElement* bone = record->FirstChildElement(); bone; bone = bone->NextSiblingElement()) {
    const std::string name = bone->Attribute("name") ? bone->Attribute("name") : "";
    std::size_t index = kBoneCount;
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      if (name == layout[b].name) index = b;
    }
    if (std::string(bone->Name()) != "bone" || index == kBoneCount) {
      throw SkeletonError(std::string("<") + kShapeElement + ">: <" + bone->Name() + " name=\"" + name +
                          "\"> is not a <bone> of the human layout");
    }
    if (seen[index]) throw SkeletonError(std::string("<") + kShapeElement + ">: bone '" + name + "' appears twice");
    seen[index] = true;
    for (int k = 0; k < 3; ++k) {
      double factor = 0.0;
      if (bone->QueryDoubleAttribute(kFactorNames[static_cast<std::size_t>(k)], &factor) != tinyxml2::XML_SUCCESS ||
          !std::isfinite(factor) || factor <= 0.0) {
        throw SkeletonError(std::string("<") + kShapeElement + ">: bone '" + name +
                            "': " + kFactorNames[static_cast<std::size_t>(k)] + " must be a positive number");
      }
      shape.scale[index][k] = factor;
    }
    if (const char* offset = bone->Attribute("offset")) {
      double x = 0.0, y = 0.0, z = 0.0;
      char extra = 0;
      if (std::sscanf(offset, "%lf %lf %lf %c", &x, &y, &z, &extra) != 3 || !std::isfinite(x) || !std::isfinite(y) ||
          !std::isfinite(z) || Eigen::Vector3d(x, y, z).cwiseAbs().maxCoeff() > kMaxShapeOffset) {
        throw SkeletonError(std::string("<") + kShapeElement + ">: bone '" + name +
                            "': offset must be three numbers within +-" + numberText(kMaxShapeOffset) + " m");
      }
      shape.offset[index] = Eigen::Vector3d(x, y, z);
    }
  }
  return shape;
}

std::string shapedUrdf(const std::string& urdf_xml, const BodyShape& shape) {
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Eigen::Vector3d& s = shape.scale[b];
    if (!s.allFinite() || (s.array() <= 0.0).any())
      throw SkeletonError("body shape factors must be finite and positive");
    if (!shape.offset[b].allFinite() || shape.offset[b].cwiseAbs().maxCoeff() > kMaxShapeOffset) {
      throw SkeletonError("body shape offsets must be finite and within +-" + numberText(kMaxShapeOffset) + " m");
    }
  }
  tinyxml2::XMLDocument document;
  parse(document, urdf_xml);
  tinyxml2::XMLElement* robot = document.FirstChildElement("robot");
  if (robot->FirstChildElement(kShapeElement)) {
    throw SkeletonError("the URDF already records a body shape: shape the unshaped URDF instead");
  }
  std::string suffix;
  const std::map<std::string, std::size_t> bones = boneLinks(*robot, suffix);
  const auto scaleOf = [&](const char* link) -> const Eigen::Vector3d* {
    const auto found = link ? bones.find(link) : bones.end();
    return found == bones.end() ? nullptr : &shape.scale[found->second];
  };
  // A joint hanging from a bone sits at the bone's scaled offset (the bone's own a, b, c); the
  // joint that places a bone (its fixed joint, or the first of its three) moves by its offset.
  // An articulated bone's link hangs from the last of its three joints, which stays at the origin.
  std::map<std::string, std::size_t> placed_by;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const BoneLayoutEntry& bone = humanBoneLayout()[b];
    placed_by[std::string(bone.name) + (bone.articulated ? "_ry_link" : "") + suffix] = b;
  }
  for (tinyxml2::XMLElement* joint = robot->FirstChildElement("joint"); joint;
       joint = joint->NextSiblingElement("joint")) {
    const tinyxml2::XMLElement* parent = joint->FirstChildElement("parent");
    const tinyxml2::XMLElement* child = joint->FirstChildElement("child");
    const Eigen::Vector3d* scale = scaleOf(parent ? parent->Attribute("link") : nullptr);
    const auto placed = child && child->Attribute("link") ? placed_by.find(child->Attribute("link")) : placed_by.end();
    const Eigen::Vector3d offset = placed == placed_by.end() ? Eigen::Vector3d::Zero() : shape.offset[placed->second];
    tinyxml2::XMLElement* origin = joint->FirstChildElement("origin");
    if ((scale || !offset.isZero(0.0)) && origin) {
      const Eigen::Vector3d xyz = parseVector(origin->Attribute("xyz"));
      origin->SetAttribute("xyz", vectorText((scale ? scale->cwiseProduct(xyz) : xyz) + offset).c_str());
    }
  }
  // A bone's visuals: placed and sized by its factors (cylinder length by c, radii by the mean of a, b).
  for (tinyxml2::XMLElement* link = robot->FirstChildElement("link"); link; link = link->NextSiblingElement("link")) {
    const Eigen::Vector3d* scale = scaleOf(link->Attribute("name"));
    if (!scale) continue;
    const double across = 0.5 * (scale->x() + scale->y());
    for (tinyxml2::XMLElement* visual = link->FirstChildElement("visual"); visual;
         visual = visual->NextSiblingElement("visual")) {
      tinyxml2::XMLElement* origin = visual->FirstChildElement("origin");
      if (origin && origin->Attribute("xyz")) {
        origin->SetAttribute("xyz", vectorText(scale->cwiseProduct(parseVector(origin->Attribute("xyz")))).c_str());
      }
      tinyxml2::XMLElement* geometry = visual->FirstChildElement("geometry");
      for (tinyxml2::XMLElement* shape_element = geometry ? geometry->FirstChildElement() : nullptr; shape_element;
           shape_element = shape_element->NextSiblingElement()) {
        if (shape_element->Attribute("radius")) {
          shape_element->SetAttribute("radius", numberText(across * shape_element->DoubleAttribute("radius")).c_str());
        }
        if (shape_element->Attribute("length")) {
          shape_element->SetAttribute("length",
                                      numberText(scale->z() * shape_element->DoubleAttribute("length")).c_str());
        }
      }
    }
  }
  robot->InsertFirstChild(document.NewComment(
      " dressed_human: the body shape (SPEC Eq. 5) below is already applied to the joint origins and the bone "
      "visuals; the node and the DressedHuman display read it back "));
  tinyxml2::XMLElement* record = document.NewElement(kShapeElement);
  robot->InsertAfterChild(robot->FirstChild(), record);
  const auto& layout = humanBoneLayout();
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    tinyxml2::XMLElement* bone = document.NewElement("bone");
    bone->SetAttribute("name", layout[b].name);
    for (int k = 0; k < 3; ++k)
      bone->SetAttribute(kFactorNames[static_cast<std::size_t>(k)], numberText(shape.scale[b][k]).c_str());
    if (!shape.offset[b].isZero(0.0)) bone->SetAttribute("offset", vectorText(shape.offset[b]).c_str());
    record->InsertEndChild(bone);
  }
  tinyxml2::XMLPrinter printer;
  document.Print(&printer);
  return printer.CStr();
}

double drawnStature(const Skeleton& skeleton, double stature) {
  return std::abs(stature - 1.0) < 0.005 || !skeleton.bodyShape().isIdentity() ? 1.0 : stature;
}

Skeleton skeletonAtStature(const Skeleton& skeleton, double stature) {
  const double drawn = drawnStature(skeleton, stature);
  if (drawn == 1.0) return skeleton;
  BodyShape tall;
  for (Eigen::Vector3d& scale : tall.scale) scale.setConstant(drawn);
  return skeleton.withBodyShape(tall);
}

}  // namespace dressed_human
