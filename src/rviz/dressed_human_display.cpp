#include "dressed_human_display.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

#include <pluginlib/class_list_macros.hpp>
#include <ros/package.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <tf2_ros/buffer.h>

#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "human_visual.h"
#include "properties/body_properties.h"
#include "properties/debug_properties.h"
#include "properties/garment_properties.h"
#include "properties/lod_properties.h"
#include "properties/relief_properties.h"

namespace dressed_human {
namespace {

constexpr double kStaleSeconds = 1.0;
// Ogre draws in float: beyond this distance from the fixed frame a human's millimetres are lost
// (float spacing at 100 km is 8 mm) and further out its coordinates overflow. No map is larger.
constexpr double kMaxDrawableCoordinate = 1e5;

bool drawable(const RigidTransform& pose) {
  return pose.translation.allFinite() && pose.translation.cwiseAbs().maxCoeff() <= kMaxDrawableCoordinate &&
         pose.rotation.coeffs().allFinite();
}

RigidTransform toRigid(const geometry_msgs::Transform& t) {
  RigidTransform rigid;
  rigid.translation = {t.translation.x, t.translation.y, t.translation.z};
  rigid.rotation = Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized();
  return rigid;
}

}  // namespace

void DressedHumanDisplay::reportError(const std::string& name, const std::string& text, bool transient) {
  setStatusStd(rviz::StatusProperty::Error, name, text);
  // Also in the log (once per new message), so headless runs and tests see what went wrong.
  // Missing TF is transient (startup, a stopped publisher): a warning there, not an error.
  std::string& last = logged_errors_[name];
  if (last != text) {
    if (transient) {
      ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", getName().toStdString().c_str(),
                     name.c_str(), text.c_str());
    } else {
      ROS_ERROR_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", getName().toStdString().c_str(),
                      name.c_str(), text.c_str());
    }
    last = text;
  }
}

void DressedHumanDisplay::clearError(const std::string& name) {
  // Called for every bone every frame: only a reported error has anything to clear.
  const auto reported = logged_errors_.find(name);
  if (reported == logged_errors_.end()) return;
  deleteStatus(QString::fromStdString(name));
  logged_errors_.erase(reported);
}

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

DressedHumanDisplay::~DressedHumanDisplay() = default;

void DressedHumanDisplay::onInitialize() {
  try {
    visual_ = std::make_unique<HumanVisual>(scene_manager_, scene_node_, "dressed_human/" + getName().toStdString() +
                                                                           "/" + std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    clearError("Material");
    ReliefMaterial::bezierEvaluationAvailable(&gpu_vertices_problem_);
  } catch (const std::exception& error) {
    reportError("Material", error.what());
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
  logged_errors_.clear();
  surfaces_reported_ = {kNotReported, kNotReported};
  stale_reported_ = false;
  undrawable_frame_.clear();  // judged again, and reported again, at the next frame
  if (visual_) visual_->setVisible(isEnabled());
  loadRobotDescription();
}

void DressedHumanDisplay::fixedFrameChanged() { context_->queueRender(); }

void DressedHumanDisplay::loadRobotDescription() {
  model_.reset();
  body_.reset();
  skeleton_.reset();
  const std::string parameter = body_properties_->descriptionParameter();
  std::string urdf;
  if (parameter.empty() || !update_nh_.getParam(parameter, urdf)) {
    reportError("URDF", "parameter '" + parameter + "' is not set");
    return;
  }
  try {
    skeleton_ = std::make_unique<Skeleton>(Skeleton::fromUrdf(urdf));
    bone_frames_.clear();
    bone_status_names_.clear();
    for (const Bone& bone : skeleton_->bones()) {
      bone_frames_.push_back(skeleton_->frameName(bone.name));
      bone_status_names_.push_back("Frame " + bone_frames_.back());
    }
    root_status_name_ = "Frame " + skeleton_->rootFrame();
    leaf_bones_.clear();
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      bool has_child = false;
      for (const Bone& other : skeleton_->bones()) has_child = has_child || other.parent == static_cast<int>(b);
      if (!has_child) leaf_bones_.push_back(static_cast<int>(b));
    }
    setStatusStd(rviz::StatusProperty::Ok, "URDF", "human skeleton '" + skeleton_->rootFrame() + "', 20 bones");
  } catch (const std::exception& error) {
    reportError("URDF", "parameter '" + parameter + "': " + error.what());
    return;
  }
  try {
    body_ = std::make_unique<BodyDescription>(loadBodyDescriptionFile(body_properties_->bodyFile(), *skeleton_));
    clearError("Body Description");
  } catch (const std::exception& error) {
    reportError("Body Description", error.what());
    return;
  }
  updateBodyShape();
}

void DressedHumanDisplay::updateBodyShape() {
  if (!body_ || !skeleton_) return;
  try {
    shape_ = scaleBodyShapeGroups(body_->shape, *skeleton_, body_properties_->shapeGroups());
  } catch (const ShapeGroupScaleError& error) {
    reportError("Body Shape", body_properties_->shapeGroupLabel(error.entry) + ": " + error.what() +
                                  "; keeping the previous shape");
    return;
  }
  clearError("Body Shape");
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
    clearError("Model");
    updateVertexEvaluation();
  } catch (const std::exception& error) {
    model_.reset();
    reportError("Model", error.what());
  }
  applyDisplacement();
  context_->queueRender();
}

void DressedHumanDisplay::updateVertexEvaluation() {
  if (!model_) return;
  std::string problem = gpu_vertices_problem_;
  for (std::size_t p = 0; problem.empty() && p < model_->parts().size(); ++p) {
    if (model_->partPatches(p).size() > ReliefMaterial::kMaxPatches) {
      problem = model_->parts()[p].name + " has " + std::to_string(model_->partPatches(p).size()) +
                " patches, the vertex shader holds " + std::to_string(ReliefMaterial::kMaxPatches);
    }
  }
  const bool gpu = lod_properties_->gpuVertices();
  if (gpu && !problem.empty()) {
    const std::string text = problem + "; the CPU evaluates the vertices";
    setStatusStd(rviz::StatusProperty::Warn, "Vertex Evaluation", text);
    ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': Vertex Evaluation: %s", getName().toStdString().c_str(),
                   text.c_str());
  } else {
    deleteStatus("Vertex Evaluation");
  }
  model_->setVertexEvaluation(gpu && problem.empty() ? VertexEvaluation::kRenderer : VertexEvaluation::kCpu);
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
    // Until a map has been generated its kind stays undisplaced; the poll that delivers it
    // calls back here.
    model_->setDisplacement(ReliefKind::kSkin, displaced ? relief_jobs_.map(ReliefKind::kSkin) : nullptr, 1.0f, 1.0f,
                            relief_properties_->skinStrength());
    model_->setDisplacement(ReliefKind::kCloth, displaced ? relief_jobs_.map(ReliefKind::kCloth) : nullptr, 1.0f,
                            ReliefMapJobs::clothHeightToTile(), relief_properties_->wrinkleStrength());
    clearError("Relief");
  } catch (const std::exception& error) {
    reportError("Relief", error.what());
  }
}

void DressedHumanDisplay::regenerateSkinRelief() {
  // Built off rviz's thread; a change meanwhile is built when the running map is done.
  relief_jobs_.requestSkin(relief_properties_->skinParameters());
}

void DressedHumanDisplay::pollReliefMaps() {
  for (const FinishedReliefMap& done : relief_jobs_.poll()) {
    const std::string status = done.kind == ReliefKind::kSkin ? "Skin relief" : "Wrinkle relief";
    if (done.map) {
      if (visual_) visual_->setNormalMap(done.kind, done.normal_rgb, done.map->width, done.map->height, 1.0f);
      clearError(status);
    } else {
      reportError(status, done.error);
    }
    updateAppearance();
  }
}

bool DressedHumanDisplay::lookUpBones() {
  const std::shared_ptr<tf2_ros::Buffer> buffer = context_->getTF2BufferPtr();
  const std::string fixed = fixed_frame_.toStdString();
  const std::string& root = skeleton_->rootFrame();
  const tf2::CompactFrameID fixed_id = buffer->_lookupFrameNumber(fixed);
  // The newest time at which the chain from the fixed frame to `frame` is known. tf2's latest
  // common time gives it without composing the chain; a lookup only runs to report an error.
  const auto newestStamp = [&](const std::string& frame) {
    ros::Time newest;
    if (fixed_id == 0 || buffer->_getLatestCommonTime(fixed_id, buffer->_lookupFrameNumber(frame), newest, nullptr) != 0) {
      newest = buffer->lookupTransform(fixed, frame, ros::Time(0)).header.stamp;  // throws what is wrong
    }
    return newest;
  };
  // One consistent time for every bone, so that garments spanning two bones never tear. Almost
  // always every bone is known at the root's newest stamp (one message carries the skeleton).
  // But TF inserts a message's transforms one by one while rviz reads, so a bone can lag its
  // root by one tick: then a lookup at that stamp fails, and all bones are looked up again at
  // the newest time every chain from the fixed frame to a leaf bone (head, hands, feet) is
  // known. Walking every chain each frame instead would cost more than the lookups themselves:
  // the TF tree is cold in the cache when rviz comes back from rendering.
  ros::Time stamp;
  bool found = false;
  try {
    stamp = newestStamp(root);
    root_ = toRigid(buffer->lookupTransform(fixed, root, stamp).transform);
    found = lookUpBonesAt(*buffer, stamp, false);
    if (!found) {
      // A chain that is missing, or lags the root by more than the stale limit (a link no
      // longer published), is left out: holding every bone back to it would freeze the human
      // without naming the culprit. Its bone's lookup fails below and reports the frame.
      const ros::Time root_stamp = stamp;
      for (const int leaf : leaf_bones_) {
        try {
          const ros::Time newest = newestStamp(bone_frames_[static_cast<std::size_t>(leaf)]);
          if ((root_stamp - newest).toSec() <= kStaleSeconds) stamp = std::min(stamp, newest);
        } catch (const tf2::TransformException&) {
        }
      }
      root_ = toRigid(buffer->lookupTransform(fixed, root, stamp).transform);
    }
    clearError(root_status_name_);
  } catch (const tf2::TransformException& error) {
    reportError(root_status_name_, error.what(), true);
    return false;
  }
  const bool stale = !stamp.isZero() && (ros::Time::now() - stamp).toSec() > kStaleSeconds;
  if (stale) {
    setStatusStd(rviz::StatusProperty::Warn, "TF",
                 "the newest skeleton transform is " + std::to_string((ros::Time::now() - stamp).toSec()) + " s old");
  } else if (stale_reported_) {
    deleteStatus("TF");
  }
  stale_reported_ = stale;
  return found || lookUpBonesAt(*buffer, stamp, true);
}

bool DressedHumanDisplay::lookUpBonesAt(const tf2_ros::Buffer& buffer, const ros::Time& stamp, bool report) {
  bool all_found = true;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    // Each bone relative to its parent, composed by the core below: tf2 then walks the three
    // links of one joint instead of the whole chain from the fixed frame every time.
    const Bone& bone = skeleton_->bone(b);
    const std::string& parent_frame = bone.parent < 0 ? skeleton_->rootFrame() : bone_frames_[static_cast<std::size_t>(bone.parent)];
    try {
      // A bone on a fixed URDF joint (clavicles, pelvis halves) sits where the URDF puts it:
      // no lookup needed, and none that could fail.
      bone_in_parent_[b] = bone.joint < 0 ? RigidTransform{bone.rest_translation, bone.rest_rotation}
                                          : toRigid(buffer.lookupTransform(parent_frame, bone_frames_[b], stamp).transform);
      clearError(bone_status_names_[b]);
    } catch (const tf2::TransformException& error) {
      if (!report) return false;
      reportError(bone_status_names_[b], error.what(), true);
      all_found = false;
    }
  }
  // Eq. 5: each joint at its parent's shaped offset; TF carries the URDF's unshaped skeleton.
  if (all_found) kinematics_->composeUnshaped(root_, bone_in_parent_, bones_);
  return all_found;
}

namespace {

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

void DressedHumanDisplay::update(float, float) {
  const double start = threadCpuSeconds();
  updateSurfaces();
  // What this display costs rviz's thread per frame (mean over ~1 s), for users and benchmarks.
  update_cpu_seconds_ += threadCpuSeconds() - start;
  if (++update_count_ == 30) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.3f ms CPU per frame", 1e3 * update_cpu_seconds_ / update_count_);
    setStatusStd(rviz::StatusProperty::Ok, "Update", text);
    update_cpu_seconds_ = 0.0;
    update_count_ = 0;
  }
}

void DressedHumanDisplay::updateSurfaces() {
  pollReliefMaps();
  if (!model_ || !visual_ || !lookUpBones() || !posesDrawable()) return;
  LevelOfDetail lod;
  if (relief_properties_->mode() == ReliefMode::kDisplacedGeometry) {
    lod.level = relief_properties_->displacementLevel();  // relief in the geometry needs vertices at its scale
  } else {
    const rviz::ViewController* view = context_->getViewManager()->getCurrent();
    lod = lod_properties_->levelOfDetail(view ? view->getCamera() : nullptr);
  }
  try {
    model_->update(root_, bones_, lod);
    visual_->update(model_->parts());
    if (debug_properties_->showSkeleton()) drawSkeleton();
    const std::array<std::size_t, 2> surfaces{model_->parts().size(), model_->triangleCount()};
    if (surfaces != surfaces_reported_) {
      setStatusStd(rviz::StatusProperty::Ok, "Surfaces",
                   std::to_string(surfaces[0]) + " parts, " + std::to_string(surfaces[1]) + " triangles");
      surfaces_reported_ = surfaces;
    }
  } catch (const std::exception& error) {
    surfaces_reported_ = {kNotReported, kNotReported};
    reportError("Surfaces", error.what());
  }
}

bool DressedHumanDisplay::posesDrawable() {
  // A glitching publisher (a huge origin, a runaway integration) must not take rviz down: Ogre
  // asserts on non-finite bounds. The human disappears, the frame is named, and it comes back
  // with sane TF.
  std::string frame;
  const RigidTransform* pose = nullptr;
  if (!drawable(root_)) frame = skeleton_->rootFrame(), pose = &root_;
  for (std::size_t b = 0; pose == nullptr && b < kBoneCount; ++b) {
    if (!drawable(bones_[b])) frame = bone_frames_[b], pose = &bones_[b];
  }
  if (pose == nullptr) {
    if (!undrawable_frame_.empty()) {
      clearError("Pose");
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
    reportError("Pose", "frame '" + frame + "' in '" + fixed_frame_.toStdString() + "' is " +
                            (finite ? std::string("at ") + position + ", beyond the 100 km rviz can draw a human at"
                                    : std::string("not finite")) +
                            "; the human is hidden until its TF is sane again");
    undrawable_frame_ = frame;
  }
  visual_->setVisible(false);  // every frame: enabling the display again must not show it
  return false;
}

void DressedHumanDisplay::drawSkeleton() {
  std::vector<Eigen::Vector3f> segments;
  segments.reserve(2 * kBoneCount);
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const double length = skeleton_->bone(b).length * shape_.scale[b].z();
    segments.push_back(bones_[b].translation.cast<float>());
    segments.push_back((bones_[b].translation + bones_[b].rotation * Eigen::Vector3d(0.0, 0.0, length)).cast<float>());
  }
  visual_->updateSkeleton(segments);
}

}  // namespace dressed_human

PLUGINLIB_EXPORT_CLASS(dressed_human::DressedHumanDisplay, rviz::Display)
