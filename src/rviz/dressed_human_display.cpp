#include "dressed_human_display.h"

#include <cmath>

#include <pluginlib/class_list_macros.hpp>
#include <ros/package.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>

#include "dressed_human/core/model/calibration_poses.h"
#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "dressed_human/core/skeleton/crowd_human_body.h"
#include "crowd_message_source.h"
#include "drawn_human.h"
#include "properties/body_properties.h"
#include "properties/crowd_properties.h"
#include "properties/debug_properties.h"
#include "properties/garment_properties.h"
#include "properties/lod_properties.h"
#include "properties/relief_properties.h"
#include "gl_renderer.h"
#include "relief_material.h"
#include "tf_bone_source.h"
#include "tf_human_roster.h"

namespace dressed_human {
namespace {

// A crowd display looks for new humans in TF this often.
constexpr float kRosterSeconds = 1.0f;
// Like RobotModelDisplay: a description not there yet (rviz opened before the launch file) is
// looked for again this often, until it is.
constexpr float kDescriptionRetrySeconds = 1.0f;

}  // namespace

DressedHumanDisplay::DressedHumanDisplay()
    : body_properties_(new BodyProperties(this)),
      crowd_properties_(new CrowdProperties(this)),
      garment_properties_(new GarmentProperties(this)),
      relief_properties_(new ReliefProperties(this)),
      lod_properties_(new LodProperties(this)),
      debug_properties_(new DebugProperties(this)) {
  // Member-function pointers: a renamed signal or slot fails to compile, not silently at run time.
  connect(body_properties_.get(), &BodyProperties::descriptionChanged, this,
          &DressedHumanDisplay::loadRobotDescription);
  connect(body_properties_.get(), &BodyProperties::shapeChanged, this, &DressedHumanDisplay::updateBodyShape);
  connect(body_properties_.get(), &BodyProperties::skinColourChanged, this, &DressedHumanDisplay::rebuildHumans);
  connect(crowd_properties_.get(), &CrowdProperties::changed, this, &DressedHumanDisplay::loadCrowdFile);
  connect(crowd_properties_.get(), &CrowdProperties::topicChanged, this, &DressedHumanDisplay::updateSubscription);
  connect(garment_properties_.get(), &GarmentProperties::changed, this, &DressedHumanDisplay::rebuildHumans);
  connect(relief_properties_.get(), &ReliefProperties::appearanceChanged, this, &DressedHumanDisplay::updateAppearance);
  connect(relief_properties_.get(), &ReliefProperties::skinMapChanged, this,
          &DressedHumanDisplay::regenerateSkinRelief);
  connect(relief_properties_.get(), &ReliefProperties::skinSizeChanged, this, &DressedHumanDisplay::resizeSkinRelief);
  connect(relief_properties_.get(), &ReliefProperties::wrinkleMapChanged, this,
          &DressedHumanDisplay::regenerateClothRelief);
  connect(lod_properties_.get(), &LodProperties::vertexEvaluationChanged, this,
          &DressedHumanDisplay::updateVertexEvaluation);
  connect(debug_properties_.get(), &DebugProperties::changed, this, &DressedHumanDisplay::updateAppearance);
}

DressedHumanDisplay::~DressedHumanDisplay() = default;

void DressedHumanDisplay::load(const rviz::Config& config) {
  rviz::Display::load(config);
  relief_properties_->loadRenamedKeys(config, getName().toStdString());
}

void DressedHumanDisplay::onInitialize() {
  ogre_ready_ = true;
  try {
    status_.clear("Material");
    ReliefMaterial::bezierEvaluationAvailable(&gpu_vertices_problem_);
    software_renderer_ = softwareRendererName();
  } catch (const std::exception& error) {
    status_.error("Material", error.what());
  }
  garment_properties_->updateVisibility();
  crowd_properties_->updateVisibility();
  loadCalibrationPoses();
  regenerateSkinRelief();
  regenerateClothRelief();
  loadCrowdFile();  // and the robot description, and every human
}

void DressedHumanDisplay::onEnable() {
  for (auto& human : humans_) human.second->visual().setVisible(true);
  updateSubscription();
}

void DressedHumanDisplay::onDisable() {
  for (auto& human : humans_) human.second->visual().setVisible(false);
  crowd_topic_.unsubscribe(status_);
}

void DressedHumanDisplay::updateSubscription() {
  if (!ogre_ready_ || !isEnabled() || !crowd_properties_->fromTopic()) return crowd_topic_.unsubscribe(status_);
  crowd_topic_.subscribe(update_nh_, crowd_properties_->topic(), status_);
  rebuildHumans();
}

// rviz resets every display when ROS time jumps back, at each loop of a replayed bag: rebuilding
// the humans there hid them for a moment every loop. As RobotModelDisplay does, the humans stay;
// their TF statuses go (they report themselves again), the others are kept up to date where they
// arise. A robot description changed since it was read is read again.
void DressedHumanDisplay::reset() {
  for (auto& human : humans_) human.second->clearStatuses(status_);
  std::string urdf;
  if (!readRobotDescription(urdf) || urdf != urdf_) loadRobotDescription();
}

// The parameter as rviz's own displays find it: searched up from rviz's namespace.
bool DressedHumanDisplay::readRobotDescription(std::string& urdf) const {
  const std::string parameter = body_properties_->descriptionParameter();
  std::string found;
  if (parameter.empty() || !update_nh_.searchParam(parameter, found)) return false;
  return update_nh_.getParam(found, urdf);
}

void DressedHumanDisplay::fixedFrameChanged() { context_->queueRender(); }

void DressedHumanDisplay::loadRobotDescription() {
  body_.reset();
  skeleton_.reset();
  urdf_.clear();
  seconds_without_description_ = 0.0f;
  const std::string parameter = body_properties_->descriptionParameter();
  std::string urdf;
  description_missing_ = !readRobotDescription(urdf);
  if (description_missing_) {
    status_.error("URDF", "parameter '" + parameter + "' is not set (looked for again every second)");
    return rebuildHumans();
  }
  try {
    skeleton_ = std::make_unique<Skeleton>(Skeleton::fromUrdf(urdf));
    urdf_ = urdf;
    status_.ok("URDF", "human skeleton '" + skeleton_->rootFrame() + "', 20 bones" +
                           (skeleton_->bodyShape().isIdentity() ? "" : ", a fitted person's proportions"));
  } catch (const std::exception& error) {
    status_.error("URDF", "parameter '" + parameter + "': " + error.what());
    return rebuildHumans();
  }
  try {
    body_ = std::make_unique<BodyDescription>(loadBodyDescriptionFile(body_properties_->bodyFile(), *skeleton_));
    // A fitted person's URDF carries its proportions: the body file's shape applies on top of them.
    body_->shape = body_->shape.appliedOn(skeleton_->bodyShape());
    shape_ = body_->shape;
    status_.clear("Body Description");
  } catch (const std::exception& error) {
    status_.error("Body Description", error.what());
  }
  updateBodyShape();
}

void DressedHumanDisplay::updateBodyShape() {
  if (body_ && skeleton_) {
    try {
      shape_ = scaleBodyShapeGroups(body_->shape, *skeleton_, body_properties_->shapeGroups());
      status_.clear("Body Shape");
    } catch (const ShapeGroupScaleError& error) {
      status_.error("Body Shape", body_properties_->shapeGroupLabel(error.entry) + ": " + error.what() +
                                      "; keeping the previous shape");
      return;
    }
  }
  rebuildHumans();
}

void DressedHumanDisplay::loadCrowdFile() {
  crowd_file_.clear();
  const std::string path = crowd_properties_->crowdFile();
  if (crowd_properties_->crowd() && !path.empty()) {
    try {
      crowd_file_ = dressed_human::loadCrowdFile(path);
      status_.clear("Crowd File");
    } catch (const CrowdFileError& error) {
      status_.error("Crowd File", std::string(error.what()) + "; humans wear what the display's properties say");
    }
  } else {
    status_.clear("Crowd File");
  }
  loadRobotDescription();
  updateSubscription();
}

void DressedHumanDisplay::rebuildHumans() {
  while (!humans_.empty()) removeHuman(humans_.begin());
  status_.clear("Humans");
  if (!skeleton_ || !body_ || !ogre_ready_) return context_->queueRender();
  if (crowd_properties_->everyHumanInTf()) {
    lookForHumans();
  } else if (crowd_properties_->fromTopic()) {
    crowd_topic_.clear();  // every human of the next message is added again
  } else {
    addHuman(skeleton_->suffix());
  }
  context_->queueRender();
}

void DressedHumanDisplay::loadCalibrationPoses() {
  const std::string walk = ros::package::getPath("dressed_human") + "/config/motions/walk.yaml";
  try {
    calibration_poses_ = calibrationPosesFromFile(walk);
    status_.clear("Level Of Detail");
  } catch (const std::exception& error) {
    calibration_poses_.clear();
    status_.warn("Level Of Detail", std::string(error.what()) +
                                        "; levels of detail are calibrated at rest alone, with a wider margin "
                                        "(more triangles for the same Max Screen Error)");
  }
}

HumanModelSettings DressedHumanDisplay::settingsFor(const std::string& suffix) const {
  HumanModelSettings settings;
  settings.calibration_poses = calibration_poses_;
  settings.skin_colour = body_properties_->skinColour();
  settings.garment_directory = ros::package::getPath("dressed_human") + "/config/garments";
  garment_properties_->apply(settings);
  if (crowd_properties_->crowd()) {
    const std::string id = suffix.empty() ? std::string() : suffix.substr(1);
    const auto listed = crowd_file_.find(id);
    if (crowd_properties_->varyUnlisted()) variedAppearance(id).applyTo(settings);
    if (listed != crowd_file_.end()) listed->second.applyTo(settings);
  }
  return settings;
}

void DressedHumanDisplay::addHuman(const std::string& suffix, double stature) {
  const bool crowd = crowd_properties_->crowd();
  const std::string label = crowd ? "body" + suffix : std::string();
  const std::string model_status = crowd ? "Model " + label : "Model";
  try {
    if (std::isnan(stature)) stature = statureInTf(*context_->getFrameManager()->getTF2BufferPtr(), *skeleton_, suffix);
    const CrowdHumanBody body = crowdHumanBody(*skeleton_, *body_, shape_, suffix, stature);
    std::unique_ptr<HumanPoseSource> poses;
    if (crowd_properties_->fromTopic()) {
      poses = std::make_unique<CrowdMessageSource>(crowd_topic_.track(suffix.substr(1)), body.skeleton);
    } else {
      poses = std::make_unique<TfBoneSource>(body.skeleton, label);
    }
    auto human = std::make_unique<DrawnHuman>(
        body.skeleton, std::move(poses), body.description, settingsFor(suffix), scene_manager_, scene_node_,
        "dressed_human/" + getName().toStdString() + "/" + std::to_string(reinterpret_cast<std::uintptr_t>(this)) +
            "/" + (suffix.empty() ? std::string("body") : suffix.substr(1)),
        label);
    DrawnHuman& added = *(humans_[suffix] = std::move(human));
    configure(added, humans_.size() == 1);
    status_.clear(model_status);
  } catch (const std::exception& error) {
    status_.error(model_status, error.what());
  }
}

void DressedHumanDisplay::configure(DrawnHuman& human, bool report) {
  human.visual().setVisible(isEnabled());
  for (const FinishedReliefMap& done : normal_maps_) {
    human.visual().setNormalMap(done);
  }
  applySkinCellSize(human);
  applyVertexEvaluation(human, report);
  applyAppearance(human);
}

void DressedHumanDisplay::lookForHumans() {
  seconds_since_roster_ = 0.0f;
  if (!skeleton_ || !body_) return;
  rviz::FrameManager& frames = *context_->getFrameManager();
  for (const std::string& suffix : freshHumansInTf(*frames.getTF2BufferPtr(), frames.getFixedFrame())) {
    if (humans_.count(suffix) == 0) addHuman(suffix, std::nan(""));  // crowd humans' heights differ
  }
  status_.ok("Humans", std::to_string(humans_.size()) + " in TF");
}

void DressedHumanDisplay::takeHumansFromTopic() {
  if (!skeleton_ || !body_) return;
  const std::size_t before = humans_.size();
  for (const CrowdTopic::NewHuman& human : crowd_topic_.takeMessages(*context_->getFrameManager(), status_)) {
    addHuman("_" + human.id, human.stature);
  }
  std::size_t left = 0;
  for (const std::string& id : crowd_topic_.takeLeft()) {
    const auto human = humans_.find("_" + id);
    if (human != humans_.end()) removeHuman(human), ++left;
  }
  if (humans_.size() != before || left > 0 || humans_.empty()) {
    status_.ok("Humans", std::to_string(humans_.size()) + " from '" + crowd_topic_.topic() + "'");
  }
}

void DressedHumanDisplay::dropLostHumans() {
  const ros::WallTime now = ros::WallTime::now();
  for (auto human = humans_.begin(); human != humans_.end();) {
    const auto next = std::next(human);
    if ((now - human->second->lastSeen()).toSec() > crowd_properties_->humanTimeout()) removeHuman(human);
    human = next;
  }
}

void DressedHumanDisplay::removeHuman(std::map<std::string, std::unique_ptr<DrawnHuman>>::iterator human) {
  human->second->clearStatuses(status_);
  humans_.erase(human);
}

void DressedHumanDisplay::updateVertexEvaluation() {
  for (auto& human : humans_) applyVertexEvaluation(*human.second, human.first == humans_.begin()->first);
  context_->queueRender();
}

void DressedHumanDisplay::applyVertexEvaluation(DrawnHuman& human, bool report) {
  const VertexEvaluationChoice choice =
      chooseVertexEvaluation(lod_properties_->vertexEvaluationRequest(), human.model(), gpu_vertices_problem_,
                             software_renderer_, ReliefMaterial::kMaxPatches);
  human.model().setVertexEvaluation(choice.evaluation);
  if (!report) return;  // every human makes the same choice: one status says it
  if (choice.status.empty()) {
    status_.clear("Vertex Evaluation");
  } else if (choice.warn) {
    status_.warn("Vertex Evaluation", choice.status, true);
  } else {
    status_.ok("Vertex Evaluation", choice.status);
  }
}

void DressedHumanDisplay::updateAppearance() {
  relief_properties_->updateVisibility();
  for (auto& human : humans_) applyAppearance(*human.second);
  context_->queueRender();
}

void DressedHumanDisplay::applyAppearance(DrawnHuman& human) {
  const bool bump = relief_properties_->mode() == ReliefMode::kBumpMapping;
  // Displaced geometry carries its relief in the mesh normals: the shader must not add it again.
  HumanVisual& visual = human.visual();
  visual.setReliefStrength(ReliefKind::kSkin, bump ? relief_properties_->skinStrength() : 0.0f);
  visual.setReliefStrength(ReliefKind::kCloth, bump ? relief_properties_->wrinkleStrength() : 0.0f);
  visual.setSkeletonVisible(debug_properties_->showSkeleton());
  try {
    human.setDisplacement(relief_jobs_, relief_properties_->mode() == ReliefMode::kDisplacedGeometry,
                          relief_properties_->skinStrength(), relief_properties_->wrinkleStrength());
    status_.clear("Relief");
  } catch (const std::exception& error) {
    status_.error("Relief", error.what());
  }
}

void DressedHumanDisplay::regenerateSkinRelief() {
  // Built off rviz's thread; a change meanwhile is built when the running map is done.
  relief_jobs_.requestSkin(relief_properties_->skinParameters());
}

void DressedHumanDisplay::regenerateClothRelief() { relief_jobs_.requestCloth(relief_properties_->foldSoftness()); }

void DressedHumanDisplay::resizeSkinRelief() {
  for (auto& human : humans_) applySkinCellSize(*human.second);
}

void DressedHumanDisplay::applySkinCellSize(DrawnHuman& human) {
  try {
    human.resetReliefVisibility(relief_properties_->skinCellSize());
    status_.clear("Skin cell size");
  } catch (const std::exception& error) {
    status_.error("Skin cell size", error.what());
  }
}

void DressedHumanDisplay::pollReliefMaps() {
  for (const FinishedReliefMap& done : relief_jobs_.poll()) {
    const std::string status = done.kind == ReliefKind::kSkin ? "Skin relief" : "Wrinkle relief";
    if (done.map) {
      normal_maps_[done.kind] = done;
      try {
        for (auto& human : humans_) human.second->visual().setNormalMap(done);
        status_.clear(status);
      } catch (const std::exception& error) {  // the texture (ReliefMaterial::setNormalMap)
        status_.error(status, error.what());
      }
    } else {
      status_.error(status, done.error);
    }
    updateAppearance();
  }
}

void DressedHumanDisplay::update(float wall_dt, float) {
  update_cost_.start();
  updateSurfaces(wall_dt);
  const std::string cost = update_cost_.stop();
  if (!cost.empty()) status_.ok("Update", cost);
}

void DressedHumanDisplay::updateSurfaces(float wall_dt) {
  pollReliefMaps();
  if (description_missing_ && (seconds_without_description_ += wall_dt) >= kDescriptionRetrySeconds) {
    seconds_without_description_ = 0.0f;
    std::string urdf;
    if (readRobotDescription(urdf)) loadRobotDescription();
  }
  if (crowd_properties_->everyHumanInTf() && (seconds_since_roster_ += wall_dt) >= kRosterSeconds) {
    dropLostHumans();
    lookForHumans();
  }
  if (crowd_properties_->fromTopic()) takeHumansFromTopic();
  const rviz::ViewController* view = context_->getViewManager()->getCurrent();
  const Ogre::Camera* camera = view ? view->getCamera() : nullptr;
  LevelOfDetail lod;
  const bool displaced = relief_properties_->mode() == ReliefMode::kDisplacedGeometry;
  if (displaced) {
    lod.level = relief_properties_->displacementLevel();  // relief in the geometry needs vertices at its scale
  } else {
    lod = lod_properties_->levelOfDetail(camera);
  }
  const bool hide_unseen_relief = lod_properties_->hideUnseenRelief() && !displaced;
  const bool hide_covered = lod_properties_->hideCovered() && !displaced;
  std::size_t parts = 0, triangles = 0;
  for (auto& human : humans_) {
    try {
      if (!human.second->update(*context_->getFrameManager(), status_, lod, camera, hide_unseen_relief, hide_covered))
        continue;
    } catch (const std::exception& error) {
      surfaces_reported_ = {};
      status_.error("Surfaces", human.second->rootFrame() + ": " + error.what());
      continue;
    }
    parts += human.second->model().parts().size();
    triangles += human.second->model().drawnTriangleCount();
  }
  reportSurfaces(humans_.size(), parts, triangles);
}

void DressedHumanDisplay::reportSurfaces(std::size_t humans, std::size_t parts, std::size_t triangles) {
  const std::array<std::size_t, 3> surfaces{humans, parts, triangles};
  if (surfaces == surfaces_reported_ || parts == 0) return;
  const std::string drawn = crowd_properties_->crowd() ? std::to_string(humans) + " humans, " : "";
  status_.ok("Surfaces", drawn + std::to_string(parts) + " parts, " + std::to_string(triangles) + " triangles");
  surfaces_reported_ = surfaces;
}

}  // namespace dressed_human

PLUGINLIB_EXPORT_CLASS(dressed_human::DressedHumanDisplay, rviz::Display)
