#include "dressed_human_display.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

#include <OgreCamera.h>
#include <OgreViewport.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/package.h>
#include <rviz/display_context.h>
#include <rviz/frame_manager.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/color_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/int_property.h>
#include <rviz/properties/string_property.h>
#include <rviz/properties/vector_property.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <tf2_ros/buffer.h>

#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "human_visual.h"

namespace dressed_human {
namespace {

enum ReliefMode { kBumpMapping = 0, kFlat = 1, kDisplacedGeometry = 2 };
enum LodMode { kAutomatic = 0, kFixed = 1 };
enum VertexSource { kGpuVertices = 0, kCpuVertices = 1 };
constexpr double kStaleSeconds = 1.0;
// Ogre draws in float: beyond this distance from the fixed frame a human's millimetres are lost
// (float spacing at 100 km is 8 mm) and further out its coordinates overflow. No map is larger.
constexpr double kMaxDrawableCoordinate = 1e5;
constexpr double kPi = 3.14159265358979323846;
// The Body Shape groups offered as properties (bodyShapeGroups() names), with their labels.
const std::vector<std::pair<std::string, std::string>> kShapeGroups{
    {"all", "All Bones"}, {"trunk", "Trunk"}, {"head_neck", "Head and Neck"}, {"arms", "Arms"}, {"legs", "Legs"}};

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

DressedHumanDisplay::DressedHumanDisplay() {
  description_property_ = new rviz::StringProperty(
      "Robot Description", "robot_description",
      "Parameter holding the human's URDF (urdf/human.urdf, optionally with a _<id> suffix).", this,
      SLOT(loadRobotDescription()));
  const std::string package = ros::package::getPath("dressed_human");
  body_file_property_ = new rviz::StringProperty(
      "Body Description", QString::fromStdString(package + "/config/bodies/default.yaml"),
      "YAML file with the skin's cross-sections and the body shape (Eq. 5).", this, SLOT(loadRobotDescription()));
  outfit_property_ = new rviz::EnumProperty("Outfit", "jacket_skirt", "What the human wears (SPEC §3).", this,
                                            SLOT(rebuildModel()));
  for (const char* outfit : {"none", "one_piece", "jacket_skirt", "jacket_pants"}) outfit_property_->addOption(outfit);
  skirt_length_property_ = new rviz::FloatProperty(
      "Skirt Length", -1.0,
      "Normalized skirt length c (Eq. 8'): 0 mini, knee length c_k, 1 long. Negative: as the garment file says.",
      this, SLOT(rebuildModel()));
  skirt_length_property_->setMax(1.0);
  file_colours_property_ = new rviz::BoolProperty("Garment Colours From Files", true,
                                                  "Use the colours of config/garments/*.yaml.", this,
                                                  SLOT(updateGarmentColourVisibility()));
  upper_colour_property_ = new rviz::ColorProperty("Upper Garment Colour", QColor(56, 82, 148),
                                                   "Jacket or one-piece.", file_colours_property_, SLOT(rebuildModel()), this);
  lower_colour_property_ = new rviz::ColorProperty("Lower Garment Colour", QColor(184, 56, 77), "Skirt or pants.",
                                                   file_colours_property_, SLOT(rebuildModel()), this);
  relief_mode_property_ = new rviz::EnumProperty(
      "Relief", "Bump mapping",
      "Bump mapping: per-pixel normals from the relief maps. Displaced geometry: the relief heights move the "
      "vertices of a finer mesh (the reference bump mapping approximates; costs far more). Flat: no relief.",
      this, SLOT(updateAppearance()));
  relief_mode_property_->addOption("Bump mapping", kBumpMapping);
  relief_mode_property_->addOption("Flat", kFlat);
  relief_mode_property_->addOption("Displaced geometry", kDisplacedGeometry);
  displacement_level_property_ = new rviz::IntProperty(
      "Displacement Level", 24, "Displaced geometry: each patch is cut n x n, whatever the level of detail (4-32).",
      relief_mode_property_, SLOT(updateAppearance()), this);
  displacement_level_property_->setMin(4);
  displacement_level_property_->setMax(Tessellator::kMaxLevel);
  relief_strength_property_ = new rviz::FloatProperty("Relief Strength", 1.0, "Scales the relief's normal tilt.",
                                                      this, SLOT(updateAppearance()));
  relief_strength_property_->setMin(0.0);
  relief_strength_property_->setMax(5.0);
  wrinkle_strength_property_ = new rviz::FloatProperty(
      "Wrinkle Strength", 0.6, "Scales the garments' buckling-wrinkle relief.", this, SLOT(updateAppearance()));
  wrinkle_strength_property_->setMin(0.0);
  wrinkle_strength_property_->setMax(5.0);
  skin_colour_property_ = new rviz::ColorProperty("Skin Colour", QColor(222, 184, 158), "Colour of the skin.", this,
                                                  SLOT(rebuildModel()));
  skin_levels_property_ = new rviz::IntProperty("Skin Relief Levels", 2, "Voronoi hierarchy depth (1-3).", this,
                                                SLOT(regenerateSkinRelief()));
  skin_levels_property_->setMin(1);
  skin_levels_property_->setMax(3);
  skin_cell_size_property_ = new rviz::FloatProperty(
      "Skin Cell Size", 1.0 / 12.0, "Level-1 cell spacing as a fraction of the relief tile.", this,
      SLOT(regenerateSkinRelief()));
  skin_cell_size_property_->setMin(0.01);
  skin_cell_size_property_->setMax(1.0);
  skin_seed_property_ = new rviz::IntProperty("Skin Seed", 1, "Random seed of the skin cells.", this,
                                              SLOT(regenerateSkinRelief()));
  skin_seed_property_->setMin(0);
  const SkinReliefParameters skin_defaults;
  skin_direction_property_ = new rviz::FloatProperty(
      "Skin Direction", 0.0, "Degrees from the patch's u axis (along the limb) that the cells are stretched along.",
      this, SLOT(regenerateSkinRelief()));
  skin_direction_property_->setMin(-180.0);
  skin_direction_property_->setMax(180.0);
  skin_stretch_property_ = new rviz::FloatProperty(
      "Skin Stretch", static_cast<float>(skin_defaults.direction_stretch),
      "Directionality: cell elongation along Skin Direction (1 = none, up to 4).", this, SLOT(regenerateSkinRelief()));
  skin_stretch_property_->setMin(1.0);
  skin_stretch_property_->setMax(4.0);
  skin_wobble_property_ = new rviz::FloatProperty(
      "Skin Wobble", static_cast<float>(skin_defaults.wobble),
      "Midpoint displacement of the cell walls, as a fraction of the wall length (0-0.3).", this,
      SLOT(regenerateSkinRelief()));
  skin_wobble_property_->setMin(0.0);
  skin_wobble_property_->setMax(0.3);
  skin_jitter_property_ = new rviz::FloatProperty(
      "Skin Jitter", static_cast<float>(skin_defaults.jitter),
      "Random seed displacement, as a fraction of the cell spacing (0 = hexagons, up to 0.5).", this,
      SLOT(regenerateSkinRelief()));
  skin_jitter_property_->setMin(0.0);
  skin_jitter_property_->setMax(0.5);
  skin_slope_property_ = new rviz::FloatProperty(
      "Skin Slope", 3.0f,  // SkinReliefParameters' default profile
      "Steepness of the cell cross-section at its wall (0.5-10).", this, SLOT(regenerateSkinRelief()));
  skin_slope_property_->setMin(0.5);
  skin_slope_property_->setMax(10.0);
  skin_roundness_property_ = new rviz::FloatProperty(
      "Skin Roundness", static_cast<float>(skin_defaults.roundness), "0: polygonal cell contours, 1: round.", this,
      SLOT(regenerateSkinRelief()));
  skin_roundness_property_->setMin(0.0);
  skin_roundness_property_->setMax(1.0);
  body_shape_category_ = new rviz::Property(
      "Body Shape", QVariant(), "Eq. 5 scale factors (a, b, c) = (x, y thickness, z length along the bone), "
      "multiplying the body file's shape; lengths move the joints, so the TF skeleton's proportions change too.",
      this);
  for (const auto& group : kShapeGroups) {
    auto* property = new rviz::VectorProperty(QString::fromStdString(group.second), Ogre::Vector3(1.0f, 1.0f, 1.0f),
                                              "(a, b, c) for this group, each in [0.2, 5].", body_shape_category_,
                                              SLOT(updateBodyShape()), this);
    shape_properties_.emplace_back(group.first, property);
  }
  show_skeleton_property_ = new rviz::BoolProperty("Show Skeleton", false,
                                                   "Draw the bones as lines, visible through skin and garments.",
                                                   this, SLOT(updateAppearance()));
  lod_mode_property_ = new rviz::EnumProperty(
      "Level of Detail", "Automatic",
      "Automatic: tessellation follows the human's size on screen. Fixed: the level below.", this);
  lod_mode_property_->addOption("Automatic", kAutomatic);
  lod_mode_property_->addOption("Fixed", kFixed);
  lod_level_property_ = new rviz::IntProperty("Tessellation Level", 6,
                                              "Fixed level: each patch is cut n x n (1-32).", this);
  lod_level_property_->setMin(1);
  lod_level_property_->setMax(32);
  lod_pixels_property_ = new rviz::FloatProperty("Max Screen Error", 1.0,
                                                 "Automatic level: largest geometric error in pixels.", this);
  lod_pixels_property_->setMin(0.1);
  vertex_evaluation_property_ = new rviz::EnumProperty(
      "Vertex Evaluation", "GPU",
      "GPU: the vertex shader evaluates the Bezier patches from their control points; rviz's thread only poses "
      "the control points. CPU: every vertex is evaluated and sent each frame. Displaced geometry is always CPU.",
      this, SLOT(updateVertexEvaluation()));
  vertex_evaluation_property_->addOption("GPU", kGpuVertices);
  vertex_evaluation_property_->addOption("CPU", kCpuVertices);
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
  updateGarmentColourVisibility();
  loadRobotDescription();
  regenerateSkinRelief();
  relief_jobs_.startCloth();
}

void DressedHumanDisplay::updateGarmentColourVisibility() {
  upper_colour_property_->setHidden(file_colours_property_->getBool());
  lower_colour_property_->setHidden(file_colours_property_->getBool());
  rebuildModel();
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
  const std::string parameter = description_property_->getStdString();
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
    body_ = std::make_unique<BodyDescription>(loadBodyDescriptionFile(body_file_property_->getStdString(), *skeleton_));
    clearError("Body Description");
  } catch (const std::exception& error) {
    reportError("Body Description", error.what());
    return;
  }
  updateBodyShape();
}

void DressedHumanDisplay::updateBodyShape() {
  if (!body_ || !skeleton_) return;
  std::vector<ShapeGroupScale> groups;
  for (const auto& entry : shape_properties_) {
    const Ogre::Vector3 abc = entry.second->getVector();
    groups.push_back({entry.first, Eigen::Vector3d(abc.x, abc.y, abc.z)});
  }
  try {
    shape_ = scaleBodyShapeGroups(body_->shape, *skeleton_, groups);
  } catch (const ShapeGroupScaleError& error) {
    reportError("Body Shape", shape_properties_[error.entry].second->getName().toStdString() + ": " + error.what() +
                                  "; keeping the previous shape");
    return;
  }
  clearError("Body Shape");
  rebuildModel();
}

void DressedHumanDisplay::rebuildModel() {
  if (!skeleton_ || !body_) return;
  HumanModelSettings settings;
  const auto rgba = [](const QColor& c) {
    return Eigen::Vector4f(static_cast<float>(c.redF()), static_cast<float>(c.greenF()), static_cast<float>(c.blueF()), 1.0f);
  };
  settings.skin_colour = rgba(skin_colour_property_->getColor());
  settings.garment_directory = ros::package::getPath("dressed_human") + "/config/garments";
  settings.skirt_length = skirt_length_property_->getFloat();
  if (!file_colours_property_->getBool()) {
    for (const char* upper : {"jacket", "one_piece"}) settings.garment_colours[upper] = rgba(upper_colour_property_->getColor());
    for (const char* lower : {"skirt", "pants"}) settings.garment_colours[lower] = rgba(lower_colour_property_->getColor());
  }
  try {
    settings.outfit = outfitFromName(outfit_property_->getStdString());
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
  const bool gpu = vertex_evaluation_property_->getOptionInt() == kGpuVertices;
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
  const bool bump = relief_mode_property_->getOptionInt() == kBumpMapping;
  displacement_level_property_->setHidden(relief_mode_property_->getOptionInt() != kDisplacedGeometry);
  // Displaced geometry carries its relief in the mesh normals: the shader must not add it again.
  visual_->setReliefStrength(ReliefKind::kSkin, bump ? relief_strength_property_->getFloat() : 0.0f);
  visual_->setReliefStrength(ReliefKind::kCloth, bump ? wrinkle_strength_property_->getFloat() : 0.0f);
  visual_->setSkeletonVisible(show_skeleton_property_->getBool());
  context_->queueRender();
}

void DressedHumanDisplay::applyDisplacement() {
  if (!model_) return;
  const bool displaced = relief_mode_property_->getOptionInt() == kDisplacedGeometry;
  try {
    // Until a map has been generated its kind stays undisplaced; the poll that delivers it
    // calls back here.
    model_->setDisplacement(ReliefKind::kSkin, displaced ? relief_jobs_.map(ReliefKind::kSkin) : nullptr, 1.0f, 1.0f,
                            relief_strength_property_->getFloat());
    model_->setDisplacement(ReliefKind::kCloth, displaced ? relief_jobs_.map(ReliefKind::kCloth) : nullptr, 1.0f,
                            ReliefMapJobs::clothHeightToTile(), wrinkle_strength_property_->getFloat());
    clearError("Relief");
  } catch (const std::exception& error) {
    reportError("Relief", error.what());
  }
}

void DressedHumanDisplay::regenerateSkinRelief() {
  // Built off rviz's thread; a change meanwhile is built when the running map is done.
  relief_jobs_.requestSkin(skinParametersFromProperties());
}

SkinReliefParameters DressedHumanDisplay::skinParametersFromProperties() const {
  SkinReliefParameters parameters;
  parameters.levels = skin_levels_property_->getInt();
  parameters.cell_size = skin_cell_size_property_->getFloat();
  parameters.seed = static_cast<std::uint32_t>(skin_seed_property_->getInt());
  parameters.direction_angle = skin_direction_property_->getFloat() * kPi / 180.0;
  parameters.direction_stretch = skin_stretch_property_->getFloat();
  parameters.wobble = skin_wobble_property_->getFloat();
  parameters.jitter = skin_jitter_property_->getFloat();
  parameters.profile = BezierProfile::fromEdgeSlope(skin_slope_property_->getFloat());
  parameters.roundness = skin_roundness_property_->getFloat();
  return parameters;
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
  lod.level = lod_level_property_->getInt();
  lod.automatic = lod_mode_property_->getOptionInt() == kAutomatic;
  if (relief_mode_property_->getOptionInt() == kDisplacedGeometry) {
    lod.automatic = false;  // relief in the geometry needs vertices at the relief's scale
    lod.level = displacement_level_property_->getInt();
  }
  if (lod.automatic) {
    const Ogre::Camera* camera = context_->getViewManager()->getCurrent()->getCamera();
    const Ogre::Vector3 eye = camera->getDerivedPosition();
    lod.camera.position = {eye.x, eye.y, eye.z};
    lod.camera.vertical_fov_radians = camera->getFOVy().valueRadians();
    lod.camera.viewport_height_pixels = camera->getViewport() ? camera->getViewport()->getActualHeight() : 1000.0;
    lod.max_error_pixels = lod_pixels_property_->getFloat();
  }
  try {
    model_->update(root_, bones_, lod);
    visual_->update(model_->parts());
    if (show_skeleton_property_->getBool()) drawSkeleton();
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
