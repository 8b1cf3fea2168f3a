#pragma once
// rviz display "dressed_human/DressedHuman": skin and garments of one human, of every human in
// TF, or of every human of a crowd topic (dressed_human/Crowd), on their skeletons' bones. Shaped like rviz's
// RobotModelDisplay: the display owns the properties (grouped by concern, properties/) and what its humans share
// (skeleton, body, relief maps); each human (DrawnHuman) reads its bones from a pose source (TF, or the crowd topic),
// turns them into surfaces (the core's HumanModel) and owns its Ogre objects (HumanVisual).

#include <array>
#include <map>
#include <memory>
#include <string>

#include <rviz/display.h>

#include "dressed_human/core/model/crowd_appearance.h"
#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "crowd_topic.h"
#include "display_status.h"
#include "update_cost_meter.h"

namespace dressed_human {

class BodyProperties;
class CrowdProperties;
class DebugProperties;
class DrawnHuman;
class GarmentProperties;
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
  void updateBodyShape();
  void loadCrowdFile();
  void updateSubscription();
  void rebuildHumans();
  void updateVertexEvaluation();
  void updateAppearance();
  void regenerateSkinRelief();
  void regenerateClothRelief();
  void resizeSkinRelief();

 private:
  // The skin cells' size on `human`'s body from the property; a bad size is the display's error.
  void applySkinCellSize(DrawnHuman& human);
  // A human of the robot description's skeleton with `suffix` ("" or "_<id>") on its frames,
  // dressed and coloured as the properties (and, for a crowd, the crowd file) say.
  // `stature`: its size against the skeleton's (a crowd message's); NaN: read from its TF.
  void addHuman(const std::string& suffix, double stature = 1.0);
  HumanModelSettings settingsFor(const std::string& suffix) const;
  // The shipped walk's poses every human's level of detail is calibrated in (calibration_poses.h).
  void loadCalibrationPoses();
  // The robot description parameter's text; false if it is not set.
  bool readRobotDescription(std::string& urdf) const;
  // Crowd: adds each human TF carries that the display lacks, and drops each one whose TF stopped.
  void lookForHumans();
  void dropLostHumans();
  // Crowd topic: the messages since the last frame; humans new to it added, those gone removed.
  void takeHumansFromTopic();
  void removeHuman(std::map<std::string, std::unique_ptr<DrawnHuman>>::iterator human);
  // A new human: the vertex evaluation (`report`: in the status), appearance, maps and
  // displacement the properties ask for.
  void configure(DrawnHuman& human, bool report);
  void applyVertexEvaluation(DrawnHuman& human, bool report);
  // Relief strengths, skeleton lines and displacement.
  void applyAppearance(DrawnHuman& human);
  void pollReliefMaps();
  void updateSurfaces(float wall_dt);
  void reportSurfaces(std::size_t humans, std::size_t parts, std::size_t triangles);

  // The properties, by concern; each group owns its rviz properties (children of this display).
  std::unique_ptr<BodyProperties> body_properties_;
  std::unique_ptr<CrowdProperties> crowd_properties_;
  std::unique_ptr<GarmentProperties> garment_properties_;
  std::unique_ptr<ReliefProperties> relief_properties_;
  std::unique_ptr<LodProperties> lod_properties_;
  std::unique_ptr<DebugProperties> debug_properties_;
  DisplayStatus status_{*this};
  // Why the Bezier vertex shader cannot run here (empty: it can).
  std::string gpu_vertices_problem_ = "the relief material did not load";
  std::string software_renderer_;  // the GL renderer if it rasterizes on the CPU (llvmpipe)
  bool ogre_ready_ = false;        // onInitialize() ran: humans may create Ogre objects

  std::unique_ptr<Skeleton> skeleton_;  // the robot description's; each human's carries its suffix
  std::string urdf_;                    // the robot description it was read from
  bool description_missing_ = false;    // its parameter was not set: looked for again
  float seconds_without_description_ = 0.0f;
  std::unique_ptr<BodyDescription> body_;                      // as the body file says
  BodyShape shape_;                                            // the file's shape times the Body Shape properties
  std::map<std::string, HumanAppearance> crowd_file_;          // by human id
  std::vector<JointAngles> calibration_poses_;                 // HumanModelSettings::calibration_poses
  std::map<std::string, std::unique_ptr<DrawnHuman>> humans_;  // by frame suffix
  float seconds_since_roster_ = 0.0f;                          // since lookForHumans()
  CrowdTopic crowd_topic_;
  // The skin and wrinkle maps, built off rviz's thread; kept for the displaced-geometry mode. The
  // newest normal map of each kind goes to every human, those added later too.
  ReliefMapJobs relief_jobs_;
  PerReliefKind<FinishedReliefMap> normal_maps_;
  // (humans, parts, triangles) the "Surfaces" status says: rebuilt only when they change.
  std::array<std::size_t, 3> surfaces_reported_{};
  UpdateCostMeter update_cost_;
};

}  // namespace dressed_human
