#pragma once
// rviz display "dressed_human/DressedHuman": skin and garments of one human, attached to the
// skeleton's TF frames. Shaped like rviz's RobotModelDisplay: the display owns the properties
// (grouped by concern, properties/) and reads TF (TfBoneSource); the core's HumanModel turns bone
// frames into surfaces; HumanVisual owns every Ogre object.

#include <array>
#include <memory>
#include <string>

#include <rviz/display.h>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/model/relief_visibility.h"
#include "display_status.h"

namespace Ogre {
class Camera;
}  // namespace Ogre

namespace dressed_human {

class BodyProperties;
class DebugProperties;
class GarmentProperties;
class HumanVisual;
class LodProperties;
class ReliefProperties;
class TfBoneSource;

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
  void updateBodyShape();
  void rebuildModel();
  void updateVertexEvaluation();
  void updateAppearance();
  void regenerateSkinRelief();

 private:
  void pollReliefMaps();
  void applyDisplacement();
  void updateSurfaces();
  // Whether every bone pose TF gave can be drawn; if not, hides the human and names the frame.
  bool posesDrawable();
  void reportUpdateCost(double cpu_seconds);
  // Feature sizes of the two reliefs on this model (ReliefVisibility), after a model or skin
  // relief change.
  void resetReliefVisibility();
  // Per frame: the plain material for a relief whose features are under two pixels.
  void updateReliefVisibility(const Ogre::Camera* camera);

  // The properties, by concern; each group owns its rviz properties (children of this display).
  std::unique_ptr<BodyProperties> body_properties_;
  std::unique_ptr<GarmentProperties> garment_properties_;
  std::unique_ptr<ReliefProperties> relief_properties_;
  std::unique_ptr<LodProperties> lod_properties_;
  std::unique_ptr<DebugProperties> debug_properties_;
  DisplayStatus status_{*this};
  // Why the Bezier vertex shader cannot run here (empty: it can).
  std::string gpu_vertices_problem_ = "the relief material did not load";
  std::string software_renderer_;  // the GL renderer if it rasterizes on the CPU (llvmpipe)

  std::unique_ptr<Skeleton> skeleton_;
  std::unique_ptr<TfBoneSource> bone_source_;  // the skeleton's frames in TF
  std::unique_ptr<BodyDescription> body_;      // as the body file says
  BodyShape shape_;                            // the file's shape times the Body Shape properties
  std::unique_ptr<ForwardKinematics> kinematics_;  // skeleton_ with shape_, composing TF's bones
  std::unique_ptr<HumanModel> model_;
  std::unique_ptr<HumanVisual> visual_;
  // The skin and wrinkle maps, built off rviz's thread; kept for the displaced-geometry mode.
  ReliefMapJobs relief_jobs_;
  std::array<RigidTransform, kBoneCount> bones_;  // in the fixed frame
  std::string undrawable_frame_;  // the frame whose pose hid the human; empty: none
  std::array<std::unique_ptr<ReliefVisibility>, 2> relief_visibility_;  // by ReliefKind; null: no such parts
  // (parts, triangles) the "Surfaces" status says: the text is rebuilt only when they change.
  static constexpr std::size_t kNotReported = static_cast<std::size_t>(-1);
  std::array<std::size_t, 2> surfaces_reported_{kNotReported, kNotReported};
  double update_cpu_seconds_ = 0.0;
  int update_count_ = 0;
};

}  // namespace dressed_human
