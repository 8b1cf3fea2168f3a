#pragma once
// The DressedHuman display's garment properties: the outfit, the skirt's length and the colours
// replacing the garment files' own.

#include <QObject>

#include "dressed_human/core/model/human_model.h"
#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

class GarmentProperties : public QObject {
  Q_OBJECT
 public:
  explicit GarmentProperties(rviz::Property* parent);

  // Sets the outfit, the skirt length and the colour overrides of `settings`; throws
  // std::invalid_argument for an unknown outfit.
  void apply(HumanModelSettings& settings) const;
  // The colour properties show only when they replace the files' colours.
  void updateVisibility();

 Q_SIGNALS:
  void changed();

 private Q_SLOTS:
  void fileColoursChanged();

 private:
  rviz::EnumProperty* outfit_;
  rviz::FloatProperty* skirt_length_;
  rviz::BoolProperty* file_colours_;
  rviz::ColorProperty* upper_colour_;
  rviz::ColorProperty* lower_colour_;
};

}  // namespace dressed_human
