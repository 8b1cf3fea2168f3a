#pragma once
// rviz display "dressed_human/DressedHuman": skin and garments of one human, attached to the
// skeleton's TF frames. Owns the properties and the TF lookups; HumanVisual owns the Ogre side.

#include <array>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <rviz/display.h>

#include "dressed_human/core/human_model.h"
#include "dressed_human/core/relief_map.h"

namespace rviz {
class BoolProperty;
class ColorProperty;
class EnumProperty;
class FloatProperty;
class IntProperty;
class StringProperty;
}  // namespace rviz

namespace dressed_human {

class HumanVisual;

class DressedHumanDisplay : public rviz::Display {
  Q_OBJECT
 public:
  DressedHumanDisplay();
  ~DressedHumanDisplay() override;

 protected:
  void onInitialize() override;
  void onEnable() override;
  void onDisable() override;
  void update(float wall_dt, float ros_dt) override;
  void reset() override;
  void fixedFrameChanged() override;

 private Q_SLOTS:
  void loadRobotDescription();
  void rebuildModel();
  void updateAppearance();
  void regenerateSkinRelief();
  void updateGarmentColourVisibility();

 private:
  bool lookUpBones();
  void updateSurfaces();
  void reportError(const std::string& name, const std::string& text, bool transient = false);
  void clearError(const std::string& name);
  void pollSkinRelief();
  void pollWrinkleRelief();

  rviz::StringProperty* description_property_;
  rviz::StringProperty* body_file_property_;
  rviz::EnumProperty* relief_mode_property_;
  rviz::FloatProperty* relief_strength_property_;
  rviz::FloatProperty* wrinkle_strength_property_;
  rviz::EnumProperty* outfit_property_;
  rviz::FloatProperty* skirt_length_property_;
  rviz::BoolProperty* file_colours_property_;
  rviz::ColorProperty* upper_colour_property_;
  rviz::ColorProperty* lower_colour_property_;
  rviz::ColorProperty* skin_colour_property_;
  rviz::IntProperty* skin_levels_property_;
  rviz::FloatProperty* skin_cell_size_property_;
  rviz::IntProperty* skin_seed_property_;
  rviz::EnumProperty* lod_mode_property_;
  rviz::IntProperty* lod_level_property_;
  rviz::FloatProperty* lod_pixels_property_;

  std::unique_ptr<Skeleton> skeleton_;
  std::vector<int> leaf_bones_;  // bones no other bone hangs from: the ends of the TF chains
  std::unique_ptr<BodyDescription> body_;
  std::unique_ptr<HumanModel> model_;
  std::unique_ptr<HumanVisual> visual_;
  // What the running skin-relief job was started with; a property change meanwhile is picked
  // up when it finishes.
  struct SkinParameterKey {
    int levels = 0;
    double cell_size = 0.0;
    std::uint32_t seed = 0;
    bool operator==(const SkinParameterKey& o) const {
      return levels == o.levels && cell_size == o.cell_size && seed == o.seed;
    }
  };
  std::future<ReliefMap> skin_relief_;
  std::future<ReliefMap> wrinkle_relief_;
  SkinParameterKey requested_skin_parameters_;
  std::map<std::string, std::string> logged_errors_;
  double update_cpu_seconds_ = 0.0;
  int update_count_ = 0;
  RigidTransform root_;
  std::array<RigidTransform, kBoneCount> bones_;
};

}  // namespace dressed_human
