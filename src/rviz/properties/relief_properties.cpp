#include "properties/relief_properties.h"

#include <algorithm>
#include <cmath>

#include <ros/console.h>
#include <rviz/config.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/int_property.h>

#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/model/skin_relief_tiling.h"
#include "dressed_human/core/surfaces/tessellation.h"
#include "properties/notifying.h"

namespace dressed_human {
namespace {

// A float property in [min, max] that asks for a new skin map.
rviz::FloatProperty* skinFloat(const char* name, double value, const char* help, double min, double max,
                               rviz::Property* parent, ReliefProperties* group) {
  auto* property = notifying(new rviz::FloatProperty(name, static_cast<float>(value), help, parent), group,
                             &ReliefProperties::skinMapChanged);
  property->setMin(static_cast<float>(min));
  property->setMax(static_cast<float>(max));
  return property;
}

}  // namespace

ReliefProperties::ReliefProperties(rviz::Property* parent) {
  mode_ = notifying(
      new rviz::EnumProperty(
          "Relief", "Bump mapping",
          "Bump mapping: per-pixel normals from the relief maps. Displaced geometry: the relief heights move the "
          "vertices of a finer mesh (the reference bump mapping approximates; costs far more). Flat: no relief.",
          parent),
      this, &ReliefProperties::appearanceChanged);
  mode_->addOption("Bump mapping", static_cast<int>(ReliefMode::kBumpMapping));
  mode_->addOption("Flat", static_cast<int>(ReliefMode::kFlat));
  mode_->addOption("Displaced geometry", static_cast<int>(ReliefMode::kDisplacedGeometry));
  displacement_level_ = notifying(
      new rviz::IntProperty("Displacement Level", 24,
                            "Displaced geometry: each patch is cut n x n, whatever the level of detail (4-32).", mode_),
      this, &ReliefProperties::appearanceChanged);
  displacement_level_->setMin(4);
  displacement_level_->setMax(Tessellator::kMaxLevel);
  skin_strength_ =
      notifying(new rviz::FloatProperty("Skin Relief Strength", 1.0, "Scales the relief's normal tilt.", parent), this,
                &ReliefProperties::appearanceChanged);
  skin_strength_->setMin(0.0);
  skin_strength_->setMax(5.0);
  wrinkle_strength_ = notifying(
      new rviz::FloatProperty("Wrinkle Strength", 0.6, "Scales the garments' buckling-wrinkle relief.", parent), this,
      &ReliefProperties::appearanceChanged);
  wrinkle_strength_->setMin(0.0);
  wrinkle_strength_->setMax(5.0);
  fold_softness_ = notifying(
      new rviz::FloatProperty("Fold Softness", static_cast<float>(kDefaultFoldSoftness),
                              "How round the garments' fold creases are, as thick or soft fabric folds: the exact "
                              "buckling folds blurred across their ridges by this much of a fold's width, and twice "
                              "as far along them (0: the exact, sharp creases; 0.2, the default: an everyday jacket "
                              "or skirt; at most 0.3).",
                              parent),
      this, &ReliefProperties::wrinkleMapChanged);
  fold_softness_->setMin(0.0);
  fold_softness_->setMax(static_cast<float>(kMaxFoldSoftness));
  levels_ = notifying(new rviz::IntProperty("Skin Relief Levels", 2, "Voronoi hierarchy depth (1-3).", parent), this,
                      &ReliefProperties::skinMapChanged);
  levels_->setMin(1);
  levels_->setMax(3);
  cell_size_ = notifying(
      new rviz::FloatProperty("Skin Cell Size (m)", static_cast<float>(SkinReliefTiling::measuredForearmSpacing()),
                              "Spacing of the skin's cells on the forearm, in metres (measured: about 1 cell per "
                              "mm^2 of adult forearm); the face, hands, trunk and limbs keep their measured "
                              "proportion to it. The relief shows only where its cells are a few pixels wide.",
                              parent),
      this, &ReliefProperties::skinSizeChanged);
  cell_size_->setMin(1e-4f);
  cell_size_->setMax(0.05f);
  seed_ = notifying(new rviz::IntProperty("Skin Seed", 1, "Random seed of the skin cells.", parent), this,
                    &ReliefProperties::skinMapChanged);
  seed_->setMin(0);
  const SkinReliefParameters defaults;
  direction_ = skinFloat("Skin Direction", 0.0,
                         "Degrees from the patch's u axis (along the limb) that the cells are stretched along.", -180.0,
                         180.0, parent, this);
  stretch_ =
      skinFloat("Skin Stretch", defaults.direction_stretch,
                "Directionality: cell elongation along Skin Direction (1 = none, up to 4).", 1.0, 4.0, parent, this);
  wobble_ = skinFloat("Skin Wobble", defaults.wobble,
                      "Midpoint displacement of the cell walls, as a fraction of the wall length (0-0.3).", 0.0, 0.3,
                      parent, this);
  jitter_ = skinFloat("Skin Jitter", defaults.jitter,
                      "Random seed displacement, as a fraction of the cell spacing (0 = hexagons, up to 0.5).", 0.0,
                      0.5, parent, this);
  slope_ = skinFloat("Skin Slope", 3.0,  // SkinReliefParameters' default profile
                     "Steepness of the cell cross-section at its wall (0.5-10).", 0.5, 10.0, parent, this);
  roundness_ =
      skinFloat("Skin Roundness", defaults.roundness, "0: polygonal cell contours, 1: round.", 0.0, 1.0, parent, this);
}

ReliefMode ReliefProperties::mode() const { return static_cast<ReliefMode>(mode_->getOptionInt()); }

int ReliefProperties::displacementLevel() const { return displacement_level_->getInt(); }

float ReliefProperties::skinStrength() const { return skin_strength_->getFloat(); }

float ReliefProperties::wrinkleStrength() const { return wrinkle_strength_->getFloat(); }

void ReliefProperties::loadRenamedKeys(const rviz::Config& config, const std::string& display) {
  float fraction = 0.0f;
  if (config.mapGetFloat("Skin Cell Size", &fraction)) {
    ROS_WARN_NAMED("dressed_human",
                   "DressedHuman display '%s': the configuration's 'Skin Cell Size' (%g of a patch's relief tile) "
                   "is ignored; the skin's cells are now sized in metres on the body: 'Skin Cell Size (m)'",
                   display.c_str(), fraction);
  }
  float strength = 0.0f;
  if (!config.mapGetFloat("Relief Strength", &strength)) return;
  const bool renamed = config.mapGetChild("Skin Relief Strength").isValid();
  if (!renamed) skin_strength_->setFloat(strength);
  ROS_WARN_NAMED("dressed_human",
                 "DressedHuman display '%s': the configuration's 'Relief Strength' is deprecated%s; "
                 "it is now 'Skin Relief Strength'",
                 display.c_str(), renamed ? " (ignored)" : "");
}

SkinReliefParameters ReliefProperties::skinParameters() const {
  SkinReliefParameters parameters;
  parameters.levels = levels_->getInt();
  parameters.cell_size = 1.0 / kSkinCellsPerTile;  // the tile's cells; their size on the body: skinCellSize()
  parameters.seed = static_cast<std::uint32_t>(seed_->getInt());
  parameters.direction_angle = direction_->getFloat() * M_PI / 180.0;
  parameters.direction_stretch = stretch_->getFloat();
  parameters.wobble = wobble_->getFloat();
  parameters.jitter = jitter_->getFloat();
  parameters.profile = BezierProfile::fromEdgeSlope(slope_->getFloat());
  parameters.roundness = roundness_->getFloat();
  return parameters;
}

double ReliefProperties::skinCellSize() const { return cell_size_->getFloat(); }

// The property's float may lie a rounding above the largest softness the core accepts.
double ReliefProperties::foldSoftness() const {
  return std::min(static_cast<double>(fold_softness_->getFloat()), kMaxFoldSoftness);
}

void ReliefProperties::updateVisibility() { displacement_level_->setHidden(mode() != ReliefMode::kDisplacedGeometry); }

}  // namespace dressed_human
