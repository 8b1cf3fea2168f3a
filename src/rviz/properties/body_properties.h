#pragma once
// The DressedHuman display's body properties: where the skeleton and the skin come from, the
// skin's colour and the Body Shape groups (Eq. 5 factors on the body file's shape).

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <QObject>

#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

class BodyProperties : public QObject {
  Q_OBJECT
 public:
  explicit BodyProperties(rviz::Property* parent);

  std::string descriptionParameter() const;  // the ROS parameter holding the URDF
  std::string bodyFile() const;
  Eigen::Vector4f skinColour() const;
  // Per Body Shape group, its bodyShapeGroups() name and (a, b, c), in property order.
  std::vector<ShapeGroupScale> shapeGroups() const;
  std::string shapeGroupLabel(std::size_t entry) const;  // the property's name, e.g. "Legs"

 Q_SIGNALS:
  void descriptionChanged();  // Robot Description or Body Description
  void shapeChanged();
  void skinColourChanged();

 private:
  rviz::StringProperty* description_;
  rviz::StringProperty* body_file_;
  rviz::ColorProperty* skin_colour_;
  rviz::Property* shape_category_;
  std::vector<std::pair<std::string, rviz::VectorProperty*>> shape_groups_;
};

}  // namespace dressed_human
