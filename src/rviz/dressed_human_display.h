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

namespace dressed_human {

class BodyProperties;
class DebugProperties;
class GarmentProperties;
class HumanVisual;
class LodProperties;
class ReliefProperties;

class DressedHumanDisplay : public rviz::Display {
  Q_OBJECT
 public:
  DressedHumanDisplay();
  ~DressedHumanDisplay() override;
  // Also accepts the configuration key "Relief Strength" (now "Skin Relief Strength").
  void load(const rviz::Config& config) override;

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

  // The properties, by concern; each group owns its rviz properties (children of this display).
  std::unique_ptr<BodyProperties> body_properties_;
  std::unique_ptr<GarmentProperties> garment_properties_;
  std::unique_ptr<ReliefProperties> relief_properties_;
  std::unique_ptr<LodProperties> lod_properties_;
  std::unique_ptr<DebugProperties> debug_properties_;
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
