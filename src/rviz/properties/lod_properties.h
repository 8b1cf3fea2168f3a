#pragma once
// The DressedHuman display's level-of-detail properties: automatic (from the camera) or fixed
// tessellation, and who evaluates the vertices (the GPU's vertex shader or the CPU).

#include <string>

#include <QObject>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/vertex_evaluation_choice.h"
#include "properties/rviz_properties_fwd.h"

namespace Ogre {
class Camera;
}  // namespace Ogre

namespace dressed_human {

class LodProperties : public QObject {
  Q_OBJECT
 public:
  explicit LodProperties(rviz::Property* parent);

  // The level of detail the properties ask for; an automatic one follows `camera` (if any).
  LevelOfDetail levelOfDetail(const Ogre::Camera* camera) const;
  bool automatic() const;

  // Who the "Vertex Evaluation" property asks to evaluate the vertices (chooseVertexEvaluation
  // decides with what the renderer allows).
  VertexEvaluationRequest vertexEvaluationRequest() const;
  // Whether a relief too small to see is drawn with the plain material (ReliefVisibility).
  bool hideUnseenRelief() const;
  // Whether what the clothes cover may be left out where it cannot be seen (LevelOfDetail::hide_covered).
  bool hideCovered() const;
  // What screen-space decisions need of `camera`.
  static CameraView cameraView(const Ogre::Camera& camera);

 Q_SIGNALS:
  void vertexEvaluationChanged();

 private:
  rviz::EnumProperty* mode_;
  rviz::IntProperty* level_;
  rviz::FloatProperty* max_error_pixels_;
  rviz::EnumProperty* vertex_evaluation_;
  rviz::BoolProperty* hide_unseen_relief_;
  rviz::BoolProperty* hide_covered_;
};

}  // namespace dressed_human
