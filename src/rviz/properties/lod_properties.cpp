#include "properties/lod_properties.h"

#include <string>

#include <OgreCamera.h>
#include <OgreViewport.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/int_property.h>

#include "properties/notifying.h"

namespace dressed_human {
namespace {

enum LodMode { kAutomatic = 0, kFixed = 1 };
enum VertexOption { kGpuVertices = 0, kCpuVertices = 1, kAutomaticVertices = 2 };  // the property's option values
// A camera rviz has not yet attached to its render panel's viewport has no height: it is judged
// as if on a panel this tall (a typical rviz view), for the frame or two until it is attached.
constexpr double kUnattachedViewportPixels = 1000.0;

}  // namespace

LodProperties::LodProperties(rviz::Property* parent) {
  mode_ = new rviz::EnumProperty("Level of Detail", "Automatic",
                                 "Automatic: tessellation follows the human's size on screen. Fixed: the level below.",
                                 parent);
  mode_->addOption("Automatic", kAutomatic);
  mode_->addOption("Fixed", kFixed);
  level_ = new rviz::IntProperty("Tessellation Level", 6, "Fixed level: each patch is cut n x n (1-32).", parent);
  level_->setMin(1);
  level_->setMax(32);
  max_error_pixels_ =
      new rviz::FloatProperty("Max Screen Error", 1.0, "Automatic level: largest geometric error in pixels.", parent);
  max_error_pixels_->setMin(0.1);
  vertex_evaluation_ = notifying(
      new rviz::EnumProperty(
          "Vertex Evaluation", "Automatic",
          "GPU: the vertex shader evaluates the Bezier patches from their control points; rviz's thread only poses "
          "the control points. CPU: every vertex is evaluated and sent each frame. Automatic: GPU on a graphics card, "
          "CPU on a software renderer (Mesa llvmpipe), whose vertex shader runs on one CPU thread. Displaced geometry "
          "is always CPU.",
          parent),
      this, &LodProperties::vertexEvaluationChanged);
  vertex_evaluation_->addOption("Automatic", kAutomaticVertices);
  vertex_evaluation_->addOption("GPU", kGpuVertices);
  vertex_evaluation_->addOption("CPU", kCpuVertices);
  hide_unseen_relief_ = new rviz::BoolProperty(
      "Hide Unseen Relief", true,
      "Draw a relief (skin cells, cloth folds) with the plain material, without its normal map, while its features "
      "cover 3 pixels or fewer on screen, where it has faded to nothing (again above 3.1 pixels): it cannot be "
      "seen there, only paid for. On a human so small that its garments' 2 cm gap covers 3 pixels or fewer, that "
      "plain lighting is computed per vertex (its triangles cover a few pixels).",
      parent);
  hide_covered_ = new rviz::BoolProperty(
      "Hide Covered Surfaces", true,
      "Leave out what the clothes cover (the skin under the jacket and skirt, their patches dropped to the coarsest "
      "level) while the gap between cloth and body (2 cm) covers 3 pixels or fewer on screen (again above 3.1 "
      "pixels): nothing of it can be seen past a hem or cuff there, and on a software renderer rasterizing it is "
      "a large part of a small human's cost.",
      parent);
}

bool LodProperties::hideUnseenRelief() const { return hide_unseen_relief_->getBool(); }

bool LodProperties::hideCovered() const { return hide_covered_->getBool(); }

CameraView LodProperties::cameraView(const Ogre::Camera& camera) {
  const Ogre::Vector3 eye = camera.getDerivedPosition();
  return CameraView{
      Eigen::Vector3d(eye.x, eye.y, eye.z), camera.getFOVy().valueRadians(),
      camera.getViewport() ? static_cast<double>(camera.getViewport()->getActualHeight()) : kUnattachedViewportPixels};
}

bool LodProperties::automatic() const { return mode_->getOptionInt() == kAutomatic; }

VertexEvaluationRequest LodProperties::vertexEvaluationRequest() const {
  switch (vertex_evaluation_->getOptionInt()) {
    case kGpuVertices:
      return VertexEvaluationRequest::kGpu;
    case kCpuVertices:
      return VertexEvaluationRequest::kCpu;
    default:
      return VertexEvaluationRequest::kAutomatic;
  }
}

LevelOfDetail LodProperties::levelOfDetail(const Ogre::Camera* camera) const {
  LevelOfDetail lod;
  lod.level = level_->getInt();
  lod.automatic = automatic();
  if (lod.automatic && camera != nullptr) {
    lod.camera = cameraView(*camera);
    lod.max_error_pixels = max_error_pixels_->getFloat();
  }
  return lod;
}

}  // namespace dressed_human
