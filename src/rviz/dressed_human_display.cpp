#include "dressed_human_display.h"

#include <cstdio>
#include <ctime>

#include <pluginlib/class_list_macros.hpp>
#include <ros/package.h>
#include <rviz/display_context.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>

#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "human_visual.h"
#include "properties/body_properties.h"
#include "properties/debug_properties.h"
#include "properties/garment_properties.h"
#include "properties/lod_properties.h"
#include "properties/relief_properties.h"
#include "tf_bone_source.h"

namespace dressed_human {
namespace {

// Ogre draws in float: beyond this distance from the fixed frame a human's millimetres are lost
// (float spacing at 100 km is 8 mm) and further out its coordinates overflow. No map is larger.
constexpr double kMaxDrawableCoordinate = 1e5;

bool drawable(const RigidTransform& pose) {
  return pose.translation.allFinite() && pose.translation.cwiseAbs().maxCoeff() <= kMaxDrawableCoordinate &&
         pose.rotation.coeffs().allFinite();
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

DressedHumanDisplay::DressedHumanDisplay()
    : body_properties_(new BodyProperties(this)),
      garment_properties_(new GarmentProperties(this)),
      relief_properties_(new ReliefProperties(this)),
      lod_properties_(new LodProperties(this)),
      debug_properties_(new DebugProperties(this)) {
  connect(body_properties_.get(), SIGNAL(descriptionChanged()), this, SLOT(loadRobotDescription()));
  connect(body_properties_.get(), SIGNAL(shapeChanged()), this, SLOT(updateBodyShape()));
  connect(body_properties_.get(), SIGNAL(skinColourChanged()), this, SLOT(rebuildModel()));
  connect(garment_properties_.get(), SIGNAL(changed()), this, SLOT(rebuildModel()));
  connect(relief_properties_.get(), SIGNAL(appearanceChanged()), this, SLOT(updateAppearance()));
  connect(relief_properties_.get(), SIGNAL(skinMapChanged()), this, SLOT(regenerateSkinRelief()));
  connect(lod_properties_.get(), SIGNAL(vertexEvaluationChanged()), this, SLOT(updateVertexEvaluation()));
  connect(debug_properties_.get(), SIGNAL(changed()), this, SLOT(updateAppearance()));
}

DressedHumanDisplay::~DressedHumanDisplay() = default;

void DressedHumanDisplay::load(const rviz::Config& config) {
  rviz::Display::load(config);
  // "Relief Strength" was renamed "Skin Relief Strength" (beside "Wrinkle Strength", the cloth's).
  float strength = 0.0f;
  if (config.mapGetFloat("Relief Strength", &strength)) {
    const bool renamed = config.mapGetChild("Skin Relief Strength").isValid();
    if (!renamed) relief_properties_->setSkinStrength(strength);
    ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': the configuration's 'Relief Strength' is deprecated%s; "
                   "it is now 'Skin Relief Strength'", getName().toStdString().c_str(), renamed ? " (ignored)" : "");
  }
}

void DressedHumanDisplay::onInitialize() {
  try {
    visual_ = std::make_unique<HumanVisual>(scene_manager_, scene_node_, "dressed_human/" + getName().toStdString() +
                                                                           "/" + std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    status_.clear("Material");
    ReliefMaterial::bezierEvaluationAvailable(&gpu_vertices_problem_);
    software_renderer_ = ReliefMaterial::softwareRenderer();
  } catch (const std::exception& error) {
    status_.error("Material", error.what());
  }
  garment_properties_->updateVisibility();
  loadRobotDescription();
  regenerateSkinRelief();
  relief_jobs_.startCloth();
}

void DressedHumanDisplay::onEnable() {
  if (visual_) visual_->setVisible(true);
}

void DressedHumanDisplay::onDisable() {
  if (visual_) visual_->setVisible(false);
}

void DressedHumanDisplay::reset() {
  rviz::Display::reset();  // clears the statuses; TF problems report themselves again
  status_.forget();
  surfaces_reported_ = {kNotReported, kNotReported};
  undrawable_frame_.clear();  // judged again, and reported again, at the next frame
  if (visual_) visual_->setVisible(isEnabled());
  loadRobotDescription();
}

void DressedHumanDisplay::fixedFrameChanged() { context_->queueRender(); }

void DressedHumanDisplay::loadRobotDescription() {
  model_.reset();
  body_.reset();
  bone_source_.reset();
  skeleton_.reset();
  const std::string parameter = body_properties_->descriptionParameter();
  std::string urdf;
  if (parameter.empty() || !update_nh_.getParam(parameter, urdf)) {
    status_.error("URDF", "parameter '" + parameter + "' is not set");
    return;
  }
  try {
    skeleton_ = std::make_unique<Skeleton>(Skeleton::fromUrdf(urdf));
    bone_source_ = std::make_unique<TfBoneSource>(*skeleton_);
    setStatusStd(rviz::StatusProperty::Ok, "URDF", "human skeleton '" + skeleton_->rootFrame() + "', 20 bones");
  } catch (const std::exception& error) {
    status_.error("URDF", "parameter '" + parameter + "': " + error.what());
    return;
  }
  try {
    body_ = std::make_unique<BodyDescription>(loadBodyDescriptionFile(body_properties_->bodyFile(), *skeleton_));
    status_.clear("Body Description");
  } catch (const std::exception& error) {
    status_.error("Body Description", error.what());
    return;
  }
  updateBodyShape();
}

void DressedHumanDisplay::updateBodyShape() {
  if (!body_ || !skeleton_) return;
  try {
    shape_ = scaleBodyShapeGroups(body_->shape, *skeleton_, body_properties_->shapeGroups());
  } catch (const ShapeGroupScaleError& error) {
    status_.error("Body Shape", body_properties_->shapeGroupLabel(error.entry) + ": " + error.what() +
                                    "; keeping the previous shape");
    return;
  }
  status_.clear("Body Shape");
  rebuildModel();
}

void DressedHumanDisplay::rebuildModel() {
  if (!skeleton_ || !body_) return;
  HumanModelSettings settings;
  settings.skin_colour = body_properties_->skinColour();
  settings.garment_directory = ros::package::getPath("dressed_human") + "/config/garments";
  try {
    garment_properties_->apply(settings);
    BodyDescription shaped = *body_;
    shaped.shape = shape_;
    model_ = std::make_unique<HumanModel>(*skeleton_, shaped, settings);
    kinematics_ = std::make_unique<ForwardKinematics>(*skeleton_, shape_);
    status_.clear("Model");
    resetReliefVisibility();
    updateVertexEvaluation();
  } catch (const std::exception& error) {
    model_.reset();
    status_.error("Model", error.what());
  }
  applyDisplacement();
  context_->queueRender();
}

void DressedHumanDisplay::updateVertexEvaluation() {
  if (!model_) return;
  const LodProperties::VertexChoice choice =
      lod_properties_->chooseVertexEvaluation(*model_, gpu_vertices_problem_, software_renderer_);
  if (choice.status.empty()) {
    deleteStatus("Vertex Evaluation");
  } else {
    setStatusStd(choice.warn ? rviz::StatusProperty::Warn : rviz::StatusProperty::Ok, "Vertex Evaluation", choice.status);
    if (choice.warn) {
      ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': Vertex Evaluation: %s", getName().toStdString().c_str(),
                     choice.status.c_str());
    }
  }
  model_->setVertexEvaluation(choice.evaluation);
  context_->queueRender();
}

void DressedHumanDisplay::updateAppearance() {
  applyDisplacement();
  if (!visual_) return;
  const bool bump = relief_properties_->mode() == ReliefMode::kBumpMapping;
  relief_properties_->updateVisibility();
  // Displaced geometry carries its relief in the mesh normals: the shader must not add it again.
  visual_->setReliefStrength(ReliefKind::kSkin, bump ? relief_properties_->skinStrength() : 0.0f);
  visual_->setReliefStrength(ReliefKind::kCloth, bump ? relief_properties_->wrinkleStrength() : 0.0f);
  visual_->setSkeletonVisible(debug_properties_->showSkeleton());
  context_->queueRender();
}

void DressedHumanDisplay::applyDisplacement() {
  if (!model_) return;
  const bool displaced = relief_properties_->mode() == ReliefMode::kDisplacedGeometry;
  try {
    // Until a map has been built its kind stays undisplaced; the poll that delivers it calls
    // back here.
    model_->setDisplacement(ReliefKind::kSkin, displaced ? relief_jobs_.map(ReliefKind::kSkin) : nullptr, 1.0f, 1.0f,
                            relief_properties_->skinStrength());
    model_->setDisplacement(ReliefKind::kCloth, displaced ? relief_jobs_.map(ReliefKind::kCloth) : nullptr, 1.0f,
                            ReliefMapJobs::clothHeightToTile(), relief_properties_->wrinkleStrength());
    status_.clear("Relief");
  } catch (const std::exception& error) {
    status_.error("Relief", error.what());
  }
}

void DressedHumanDisplay::regenerateSkinRelief() {
  // Built off rviz's thread; a change meanwhile is built when the running map is done.
  relief_jobs_.requestSkin(relief_properties_->skinParameters());
  resetReliefVisibility();
}

void DressedHumanDisplay::resetReliefVisibility() {
  if (!model_) return;
  // Both reliefs are tiled once per patch: skin cells at the cell size's fraction of a tile,
  // cloth folds about half a buckling cell apart (cells_around cells per tile).
  const double skin = model_->reliefTileSize(ReliefKind::kSkin) * relief_properties_->skinParameters().cell_size;
  const double cloth = model_->reliefTileSize(ReliefKind::kCloth) / (2.0 * garmentWrinkleMapSpec().cells_around);
  relief_visibility_[0] = skin > 0.0 ? std::make_unique<ReliefVisibility>(skin) : nullptr;
  relief_visibility_[1] = cloth > 0.0 ? std::make_unique<ReliefVisibility>(cloth) : nullptr;
  if (visual_) {
    visual_->setReliefShown(ReliefKind::kSkin, true);
    visual_->setReliefShown(ReliefKind::kCloth, true);
  }
}

void DressedHumanDisplay::updateReliefVisibility(const Ogre::Camera* camera) {
  const Eigen::AlignedBox3f bounds = model_->bounds();
  const bool judged = camera != nullptr && lod_properties_->hideUnseenRelief() && !bounds.isEmpty() &&
                      relief_properties_->mode() == ReliefMode::kBumpMapping;
  double pixels_per_metre = 0.0;  // at the human's nearest point
  if (judged) {
    const CameraView view = LodProperties::cameraView(*camera);
    pixels_per_metre = pixelsPerMetre(view, bounds.cast<double>().exteriorDistance(view.position));
  }
  for (const ReliefKind kind : {ReliefKind::kSkin, ReliefKind::kCloth}) {
    std::unique_ptr<ReliefVisibility>& visibility = relief_visibility_[kind == ReliefKind::kSkin ? 0 : 1];
    if (visibility) visual_->setReliefShown(kind, judged ? visibility->update(pixels_per_metre) : true);
  }
}

void DressedHumanDisplay::pollReliefMaps() {
  for (const FinishedReliefMap& done : relief_jobs_.poll()) {
    const std::string status = done.kind == ReliefKind::kSkin ? "Skin relief" : "Wrinkle relief";
    if (done.map) {
      if (visual_) visual_->setNormalMap(done.kind, done.normal_rgb, done.map->width, done.map->height, 1.0f);
      status_.clear(status);
    } else {
      status_.error(status, done.error);
    }
    updateAppearance();
  }
}

void DressedHumanDisplay::update(float, float) {
  const double start = threadCpuSeconds();
  updateSurfaces();
  reportUpdateCost(threadCpuSeconds() - start);
}

void DressedHumanDisplay::reportUpdateCost(double cpu_seconds) {
  // What this display costs rviz's thread per frame (mean over ~1 s), for users and benchmarks.
  update_cpu_seconds_ += cpu_seconds;
  if (++update_count_ < 30) return;
  char text[64];
  std::snprintf(text, sizeof(text), "%.3f ms CPU per frame", 1e3 * update_cpu_seconds_ / update_count_);
  setStatusStd(rviz::StatusProperty::Ok, "Update", text);
  update_cpu_seconds_ = 0.0;
  update_count_ = 0;
}

void DressedHumanDisplay::updateSurfaces() {
  pollReliefMaps();
  if (!model_ || !visual_ || !bone_source_->lookUp(*context_->getFrameManager(), status_)) return;
  // Eq. 5: each joint at its parent's shaped offset; TF carries the URDF's unshaped skeleton.
  kinematics_->composeUnshaped(bone_source_->root(), bone_source_->bonesInParent(), bones_);
  if (!posesDrawable()) return;
  LevelOfDetail lod;
  const rviz::ViewController* view = context_->getViewManager()->getCurrent();
  if (relief_properties_->mode() == ReliefMode::kDisplacedGeometry) {
    lod.level = relief_properties_->displacementLevel();  // relief in the geometry needs vertices at its scale
  } else {
    lod = lod_properties_->levelOfDetail(view ? view->getCamera() : nullptr);
  }
  try {
    model_->update(bone_source_->root(), bones_, lod);
    visual_->update(model_->parts());
    updateReliefVisibility(view ? view->getCamera() : nullptr);
    visual_->updateSkeleton(*kinematics_, bones_);
    const std::array<std::size_t, 2> surfaces{model_->parts().size(), model_->triangleCount()};
    if (surfaces != surfaces_reported_) {
      setStatusStd(rviz::StatusProperty::Ok, "Surfaces",
                   std::to_string(surfaces[0]) + " parts, " + std::to_string(surfaces[1]) + " triangles");
      surfaces_reported_ = surfaces;
    }
  } catch (const std::exception& error) {
    surfaces_reported_ = {kNotReported, kNotReported};
    status_.error("Surfaces", error.what());
  }
}

bool DressedHumanDisplay::posesDrawable() {
  // A glitching publisher (a huge origin, a runaway integration) must not take rviz down: Ogre
  // asserts on non-finite bounds. The human disappears, the frame is named, and it comes back
  // with sane TF.
  std::string frame;
  const RigidTransform* pose = nullptr;
  if (!drawable(bone_source_->root())) frame = bone_source_->rootFrame(), pose = &bone_source_->root();
  for (std::size_t b = 0; pose == nullptr && b < kBoneCount; ++b) {
    if (!drawable(bones_[b])) frame = bone_source_->boneFrame(b), pose = &bones_[b];
  }
  if (pose == nullptr) {
    if (!undrawable_frame_.empty()) {
      status_.clear("Pose");
      visual_->setVisible(true);
      undrawable_frame_.clear();
    }
    return true;
  }
  if (undrawable_frame_ != frame) {
    char position[96];
    std::snprintf(position, sizeof(position), "(%.2g, %.2g, %.2g) m", pose->translation.x(), pose->translation.y(),
                  pose->translation.z());
    const bool finite = pose->translation.allFinite() && pose->rotation.coeffs().allFinite();
    status_.error("Pose", "frame '" + frame + "' in '" + fixed_frame_.toStdString() + "' is " +
                              (finite ? std::string("at ") + position + ", beyond the 100 km rviz can draw a human at"
                                      : std::string("not finite")) +
                              "; the human is hidden until its TF is sane again");
    undrawable_frame_ = frame;
  }
  visual_->setVisible(false);  // every frame: enabling the display again must not show it
  return false;
}

}  // namespace dressed_human

PLUGINLIB_EXPORT_CLASS(dressed_human::DressedHumanDisplay, rviz::Display)
