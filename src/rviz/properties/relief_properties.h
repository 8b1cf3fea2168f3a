#pragma once
// The DressedHuman display's relief properties: how the relief is drawn (bump mapping, flat,
// displaced geometry), how strong the skin's and the cloth's relief are, and the skin relief's
// Voronoi cells (SkinReliefParameters).

#include <string>

#include <QObject>

#include "dressed_human/core/relief/skin_relief.h"
#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

enum class ReliefMode { kBumpMapping = 0, kFlat = 1, kDisplacedGeometry = 2 };

class ReliefProperties : public QObject {
  Q_OBJECT
 public:
  explicit ReliefProperties(rviz::Property* parent);

  ReliefMode mode() const;
  int displacementLevel() const;  // displaced geometry: each patch cut n x n
  float skinStrength() const;
  float wrinkleStrength() const;
  // A configuration saved before "Relief Strength" was renamed "Skin Relief Strength" (beside
  // "Wrinkle Strength", the cloth's) still sets it, with a deprecation warning naming `display`;
  // where both keys are saved, the new one wins.
  void loadRenamedKeys(const rviz::Config& config, const std::string& display);
  // A configuration saved before issue 40 holds "Skin Cell Size" as a fraction of a patch's tile:
  // it has no size in metres, so it is ignored with a warning naming `display`.
  SkinReliefParameters skinParameters() const;
  // Level-1 skin cell spacing on the forearm (m); the other regions in their measured proportion.
  double skinCellSize() const;
  // The garments' fold softness (garmentWrinkleMapSpec: cells; 0 exact creases).
  double foldSoftness() const;
  // Displacement Level shows only with displaced geometry.
  void updateVisibility();

 Q_SIGNALS:
  void appearanceChanged();  // mode, strengths, displacement level
  void skinMapChanged();     // a skin-relief parameter: the map must be built again
  void skinSizeChanged();    // the skin cells' size on the body: the tiling changes, not the map
  void wrinkleMapChanged();  // the fold softness: the wrinkle map must be built again

 private:
  rviz::EnumProperty* mode_;
  rviz::IntProperty* displacement_level_;
  rviz::FloatProperty* skin_strength_;
  rviz::FloatProperty* wrinkle_strength_;
  rviz::FloatProperty* fold_softness_;
  rviz::IntProperty* levels_;
  rviz::FloatProperty* cell_size_;
  rviz::IntProperty* seed_;
  rviz::FloatProperty* direction_;
  rviz::FloatProperty* stretch_;
  rviz::FloatProperty* wobble_;
  rviz::FloatProperty* jitter_;
  rviz::FloatProperty* slope_;
  rviz::FloatProperty* roundness_;
};

}  // namespace dressed_human
