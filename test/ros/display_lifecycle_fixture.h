#pragma once
// The display lifecycle tests' rviz: one VisualizationManager for the program, a DressedHuman
// display in it, and what the tests look at (statuses, figure pixels on screen, views).
#include <algorithm>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <QApplication>
#include <ros/ros.h>
#include <rviz/config.h>
#include <rviz/display.h>
#include <rviz/properties/status_property.h>
#include <rviz/properties/vector_property.h>
#include <OgreMaterialManager.h>
#include <OgreMovableObject.h>
#include <OgreRenderWindow.h>
#include <OgreSceneNode.h>
#include <OgreTechnique.h>
#include <rviz/render_panel.h>
#include <rviz/frame_manager.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <rviz/visualization_manager.h>
#include <tf2_ros/transform_broadcaster.h>
#include <urdf_parser/urdf_parser.h>

#include "dressed_human/Crowd.h"

namespace display_lifecycle {

inline long residentKilobytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

// TF of a human standing in the URDF's rest pose at (x, 0, 1), now: every joint of `model` with
// `suffix` appended to its frame names, except the one whose child link is `left_out`.
inline std::vector<geometry_msgs::TransformStamped> restPoseTransforms(const urdf::ModelInterface& model,
                                                                       const std::string& suffix, double x,
                                                                       const std::string& left_out = "") {
  std::vector<geometry_msgs::TransformStamped> transforms;
  geometry_msgs::TransformStamped root;
  root.header.stamp = ros::Time::now();
  root.header.frame_id = "world";
  root.child_frame_id = model.getRoot()->name + suffix;
  root.transform.translation.x = x;
  root.transform.translation.z = 1.0;
  root.transform.rotation.w = 1.0;
  transforms.push_back(root);
  for (const auto& entry : model.joints_) {
    const urdf::Joint& joint = *entry.second;
    if (joint.child_link_name == left_out) continue;
    geometry_msgs::TransformStamped transform = root;
    transform.header.frame_id = joint.parent_link_name + suffix;
    transform.child_frame_id = joint.child_link_name + suffix;
    const urdf::Pose& origin = joint.parent_to_joint_origin_transform;
    transform.transform.translation.x = origin.position.x;
    transform.transform.translation.y = origin.position.y;
    transform.transform.translation.z = origin.position.z;
    origin.rotation.getQuaternion(transform.transform.rotation.x, transform.transform.rotation.y,
                                  transform.transform.rotation.z, transform.transform.rotation.w);
    transforms.push_back(transform);
  }
  return transforms;
}

class DisplayLifecycleTest : public ::testing::Test {
 protected:
  // One rviz for the whole program: rviz registers its shared Ogre materials once per process,
  // so a second VisualizationManager would fail.
  static void SetUpTestSuite() {
    if (manager_ != nullptr) return;
    panel_ = new rviz::RenderPanel;
    manager_ = new rviz::VisualizationManager(panel_);
    panel_->resize(320, 240);
    panel_->show();
    panel_->initialize(manager_->getSceneManager(), manager_);
    manager_->initialize();
    manager_->setFixedFrame("world");
    display_ = manager_->createDisplay("dressed_human/DressedHuman", "human", true);
  }

  // One rviz frame: Qt events, ROS callbacks (TF), then the displays' update() and a render.
  void frame() {
    QApplication::processEvents();
    ros::spinOnce();
    QMetaObject::invokeMethod(manager_, "onUpdate", Qt::DirectConnection);
  }
  void frames(int count) {
    for (int i = 0; i < count; ++i) frame();
  }
  // The display's status list is the child named "Status: <level>"; it exists once the display
  // has reported anything. "No status yet" counts as Error here.
  rviz::StatusProperty::Level level() const {
    for (int i = 0; i < display_->numChildren(); ++i) {
      if (auto* status = dynamic_cast<rviz::StatusProperty*>(display_->childAt(i))) return status->getLevel();
    }
    return rviz::StatusProperty::Error;
  }
  // True once the display has built the human's geometry (its "Surfaces" status exists): ready
  // to be looked at, not yet seen; drawnOnScreen() looks.
  bool reported() const {
    for (int i = 0; i < display_->numChildren(); ++i) {
      auto* list = dynamic_cast<rviz::StatusProperty*>(display_->childAt(i));
      for (int s = 0; list && s < list->numChildren(); ++s) {
        if (list->childAt(s)->getName() == "Surfaces") return true;
      }
    }
    return false;
  }
  // Pixels of the render window unlike its background (a corner's colour, rviz's plain one).
  int figurePixels() const {
    Ogre::RenderWindow* window = panel_->getRenderWindow();
    std::vector<unsigned char> rgb(window->getWidth() * window->getHeight() * 3);
    window->copyContentsToMemory(
        Ogre::Box(0, 0, window->getWidth(), window->getHeight()),
        Ogre::PixelBox(window->getWidth(), window->getHeight(), 1, Ogre::PF_BYTE_RGB, rgb.data()));
    const unsigned char background = rgb[0];
    int figure = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
      if (std::abs(rgb[i] - background) + std::abs(rgb[i + 1] - background) + std::abs(rgb[i + 2] - background) > 30)
        ++figure;
    }
    return figure;
  }
  // Drawn means on screen: the view on the human's body frame 4 m away, its figure covers at
  // least kDrawnPixels of the suite's 320 x 240 panel (measured: over 1,500 in every outfit; none
  // with the display's scene node hidden). The view is put back as it was.
  static constexpr int kDrawnPixels = 1000;
  bool drawnOnScreen() {
    rviz::ViewController* view = manager_->getViewManager()->getCurrent();
    const QVariant distance = view->subProp("Distance")->getValue();
    const QVariant focal = view->subProp("Focal Point")->getValue();
    focusOnHuman();
    view->subProp("Distance")->setValue(4.0);
    frames(3);
    const int figure = figurePixels();
    view->subProp("Distance")->setValue(distance);
    view->subProp("Focal Point")->setValue(focal);
    frames(1);
    return figure >= kDrawnPixels;
  }
  std::string allStatuses() const {
    std::string text;
    for (int i = 0; i < display_->numChildren(); ++i) {
      auto* list = dynamic_cast<rviz::StatusProperty*>(display_->childAt(i));
      for (int s = 0; list && s < list->numChildren(); ++s)
        text += list->childAt(s)->getName().toStdString() + " = " +
                list->childAt(s)->getValue().toString().toStdString() + "\n";
    }
    return text;
  }
  // The view's focal point on the human's body frame, wherever the walk (mode replay: straight
  // on) has taken it: a human outside the view is not updated at all.
  void focusOnHuman() {
    rviz::ViewController* view = manager_->getViewManager()->getCurrent();
    ASSERT_NE(view, nullptr);
    if (!default_distance_.isValid()) {
      default_distance_ = view->subProp("Distance")->getValue();
      default_focal_ = view->subProp("Focal Point")->getValue();
    }
    Ogre::Vector3 body;
    Ogre::Quaternion unused;
    ASSERT_TRUE(manager_->getFrameManager()->getTransform("body", ros::Time(), body, unused));
    view->subProp("Focal Point")->setValue(QVariant(QString("%1;%2;%3").arg(body.x).arg(body.y).arg(body.z)));
  }
  // The human tiny on screen (rviz's default orbit distance in a 60 px view) or large (a 1200 px
  // view 2 m from its body frame), then ten frames.
  void viewHuman(bool near) { viewHuman(near ? 1200 : 60, near ? QVariant(2.0) : default_distance_); }
  // The human in a panel `height` pixels high from `distance` (m; invalid: rviz's default view's).
  void viewHuman(int height, const QVariant& distance) {
    focusOnHuman();
    panel_->resize(height * 4 / 3, height);
    manager_->getViewManager()
        ->getCurrent()
        ->subProp("Distance")
        ->setValue(distance.isValid() ? distance : default_distance_);
    frames(10);
  }
  // rviz's default view in the suite's 320 x 240 panel again.
  void restoreView() {
    rviz::ViewController* view = manager_->getViewManager()->getCurrent();
    if (view != nullptr && default_distance_.isValid()) {
      view->subProp("Distance")->setValue(default_distance_);
      view->subProp("Focal Point")->setValue(default_focal_);
    }
    panel_->resize(320, 240);
    frames(5);
  }
  QVariant default_distance_, default_focal_;  // of rviz's view, kept by viewHuman()
  // The status called `name`, or nullptr.
  const rviz::StatusProperty* status(const QString& name) const {
    for (int i = 0; i < display_->numChildren(); ++i) {
      auto* list = dynamic_cast<rviz::StatusProperty*>(display_->childAt(i));
      for (int s = 0; list && s < list->numChildren(); ++s) {
        if (list->childAt(s)->getName() == name) return dynamic_cast<rviz::StatusProperty*>(list->childAt(s));
      }
    }
    return nullptr;
  }
  // Statuses at Error level other than `expected`, as "name: text" (empty: none).
  std::string unexpectedErrors(const QString& expected) const {
    std::string errors;
    for (int i = 0; i < display_->numChildren(); ++i) {
      auto* list = dynamic_cast<rviz::StatusProperty*>(display_->childAt(i));
      for (int s = 0; list && s < list->numChildren(); ++s) {
        auto* status = dynamic_cast<rviz::StatusProperty*>(list->childAt(s));
        if (status && status->getLevel() == rviz::StatusProperty::Error && status->getName() != expected) {
          errors += status->getName().toStdString() + ": " + status->getValue().toString().toStdString() + "\n";
        }
      }
    }
    return errors;
  }

  inline static rviz::RenderPanel* panel_ = nullptr;
  inline static rviz::VisualizationManager* manager_ = nullptr;
  inline static rviz::Display* display_ = nullptr;
  rviz::VectorProperty* legs_ = nullptr;
};

}  // namespace display_lifecycle
