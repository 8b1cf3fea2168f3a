#include "properties/body_properties.h"

#include <ros/package.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/string_property.h>
#include <rviz/properties/vector_property.h>

#include "properties/property_colour.h"
#include "properties/notifying.h"

namespace dressed_human {
namespace {

// The Body Shape groups offered (bodyShapeGroups() names), with their labels.
const std::vector<std::pair<std::string, std::string>> kShapeGroups{
    {"all", "All Bones"}, {"trunk", "Trunk"}, {"head_neck", "Head and Neck"}, {"arms", "Arms"}, {"legs", "Legs"}};

}  // namespace

BodyProperties::BodyProperties(rviz::Property* parent) {
  description_ =
      notifying(new rviz::StringProperty(
                    "Robot Description", "robot_description",
                    "Parameter holding the human's URDF (urdf/human.urdf, optionally with a _<id> suffix).", parent),
                this, &BodyProperties::descriptionChanged);
  const std::string package = ros::package::getPath("dressed_human");
  body_file_ = notifying(
      new rviz::StringProperty("Body Description", QString::fromStdString(package + "/config/bodies/default.yaml"),
                               "YAML file with the skin's cross-sections and the body shape (Eq. 5).", parent),
      this, &BodyProperties::descriptionChanged);
  skin_colour_ = notifying(new rviz::ColorProperty("Skin Colour", QColor(222, 184, 158), "Colour of the skin.", parent),
                           this, &BodyProperties::skinColourChanged);
  shape_category_ = new rviz::Property(
      "Body Shape", QVariant(),
      "Eq. 5 scale factors (a, b, c) = (x, y thickness, z length along the bone), "
      "multiplying the body file's shape; lengths move the joints, so the TF skeleton's proportions change too.",
      parent);
  for (const auto& group : kShapeGroups) {
    auto* property =
        notifying(new rviz::VectorProperty(QString::fromStdString(group.second), Ogre::Vector3(1.0f, 1.0f, 1.0f),
                                           "(a, b, c) for this group, each in [0.2, 5].", shape_category_),
                  this, &BodyProperties::shapeChanged);
    shape_groups_.emplace_back(group.first, property);
  }
}

std::string BodyProperties::descriptionParameter() const { return description_->getStdString(); }

std::string BodyProperties::bodyFile() const { return body_file_->getStdString(); }

Eigen::Vector4f BodyProperties::skinColour() const { return opaqueRgba(skin_colour_->getColor()); }

std::vector<ShapeGroupScale> BodyProperties::shapeGroups() const {
  std::vector<ShapeGroupScale> groups;
  for (const auto& entry : shape_groups_) {
    const Ogre::Vector3 abc = entry.second->getVector();
    groups.push_back({entry.first, Eigen::Vector3d(abc.x, abc.y, abc.z)});
  }
  return groups;
}

std::string BodyProperties::shapeGroupLabel(std::size_t entry) const {
  return shape_groups_.at(entry).second->getName().toStdString();
}

}  // namespace dressed_human
