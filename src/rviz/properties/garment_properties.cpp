#include "properties/garment_properties.h"

#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>

#include "properties/property_colour.h"
#include "properties/notifying.h"

namespace dressed_human {

GarmentProperties::GarmentProperties(rviz::Property* parent) {
  outfit_ = notifying(new rviz::EnumProperty("Outfit", "jacket_skirt", "What the human wears (SPEC §3).", parent), this,
                      &GarmentProperties::changed);
  for (const char* outfit : {"none", "one_piece", "jacket_skirt", "jacket_pants"}) outfit_->addOption(outfit);
  skirt_length_ = notifying(
      new rviz::FloatProperty(
          "Skirt Length", -1.0,
          "Normalized skirt length c (Eq. 8'): 0 mini, knee length c_k, 1 long. Negative: as the garment file says.",
          parent),
      this, &GarmentProperties::changed);
  skirt_length_->setMax(1.0);
  file_colours_ = notifying(
      new rviz::BoolProperty("Garment Colours From Files", true, "Use the colours of config/garments/*.yaml.", parent),
      this, &GarmentProperties::fileColoursChanged);
  upper_colour_ = notifying(
      new rviz::ColorProperty("Upper Garment Colour", QColor(56, 82, 148), "Jacket or one-piece.", file_colours_), this,
      &GarmentProperties::changed);
  lower_colour_ =
      notifying(new rviz::ColorProperty("Lower Garment Colour", QColor(184, 56, 77), "Skirt or pants.", file_colours_),
                this, &GarmentProperties::changed);
}

void GarmentProperties::apply(HumanModelSettings& settings) const {
  settings.skirt_length = skirt_length_->getFloat();
  if (!file_colours_->getBool()) {
    for (const char* upper : {"jacket", "one_piece"})
      settings.garment_colours[upper] = opaqueRgba(upper_colour_->getColor());
    for (const char* lower : {"skirt", "pants"})
      settings.garment_colours[lower] = opaqueRgba(lower_colour_->getColor());
  }
  settings.outfit = outfitFromName(outfit_->getStdString());
}

void GarmentProperties::updateVisibility() {
  upper_colour_->setHidden(file_colours_->getBool());
  lower_colour_->setHidden(file_colours_->getBool());
}

void GarmentProperties::fileColoursChanged() {
  updateVisibility();
  Q_EMIT changed();
}

}  // namespace dressed_human
