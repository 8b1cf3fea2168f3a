#pragma once
// rviz display "dressed_human/DressedHuman": skin and garments of one human, attached to the
// skeleton's TF frames. Owns the properties and the TF lookups; HumanVisual owns the Ogre side.

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ros/time.h>
#include <rviz/display.h>
#include <tf2_ros/buffer.h>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/relief/skin_relief.h"

namespace rviz {
class BoolProperty;
class ColorProperty;
class EnumProperty;
class FloatProperty;
class IntProperty;
class Property;
class StringProperty;
class VectorProperty;
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
  void updateBodyShape();
  void updateVertexEvaluation();

 private:
  bool lookUpBones();
  // Every bone at `stamp`; false at the first failure, or (report) after reporting each one.
  bool lookUpBonesAt(const tf2_ros::Buffer& buffer, const ros::Time& stamp, bool report);
  // Whether every bone pose TF gave can be drawn; if not, hides the human and names the frame.
  bool posesDrawable();
  void updateSurfaces();
  void reportError(const std::string& name, const std::string& text, bool transient = false);
  void clearError(const std::string& name);
  void pollReliefMaps();
  void applyDisplacement();
  void drawSkeleton();
  SkinReliefParameters skinParametersFromProperties() const;

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
  rviz::FloatProperty* skin_direction_property_;
  rviz::FloatProperty* skin_stretch_property_;
  rviz::FloatProperty* skin_wobble_property_;
  rviz::FloatProperty* skin_jitter_property_;
  rviz::FloatProperty* skin_slope_property_;
  rviz::FloatProperty* skin_roundness_property_;
  rviz::IntProperty* displacement_level_property_;
  rviz::Property* body_shape_category_;
  // (a, b, c) of Eq. 5 per limb group of bodyShapeGroups(), multiplying the body file's shape.
  std::vector<std::pair<std::string, rviz::VectorProperty*>> shape_properties_;
  rviz::BoolProperty* show_skeleton_property_;
  rviz::EnumProperty* lod_mode_property_;
  rviz::IntProperty* lod_level_property_;
  rviz::FloatProperty* lod_pixels_property_;
  rviz::EnumProperty* vertex_evaluation_property_;
  // Why the Bezier vertex shader cannot run here (empty: it can).
  std::string gpu_vertices_problem_ = "the relief material did not load";

  std::unique_ptr<Skeleton> skeleton_;
  std::vector<int> leaf_bones_;  // bones no other bone hangs from: the ends of the TF chains
  // Per bone its TF frame and the status reporting it, named once per URDF (every frame uses them).
  std::vector<std::string> bone_frames_;
  std::vector<std::string> bone_status_names_;
  std::string root_status_name_;
  bool stale_reported_ = false;
  std::string undrawable_frame_;  // the frame whose pose hid the human; empty: none
  // (parts, triangles) the "Surfaces" status says: the text is rebuilt only when they change.
  static constexpr std::size_t kNotReported = static_cast<std::size_t>(-1);
  std::array<std::size_t, 2> surfaces_reported_{kNotReported, kNotReported};
  std::unique_ptr<BodyDescription> body_;   // as the body file says
  BodyShape shape_;                         // the file's shape times the Body Shape properties
  std::unique_ptr<HumanModel> model_;
  std::unique_ptr<HumanVisual> visual_;
  std::unique_ptr<ForwardKinematics> kinematics_;  // the skeleton with shape_, composing TF's bones
  // The skin and wrinkle maps, built off rviz's thread; kept for the displaced-geometry mode.
  ReliefMapJobs relief_jobs_;
  std::map<std::string, std::string> logged_errors_;
  double update_cpu_seconds_ = 0.0;
  int update_count_ = 0;
  RigidTransform root_;
  std::array<RigidTransform, kBoneCount> bone_in_parent_;  // as TF carries them, unshaped
  std::array<RigidTransform, kBoneCount> bones_;
};

}  // namespace dressed_human
