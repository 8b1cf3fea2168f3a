#pragma once
// ROS adapter: walks every human of a crowd in one process and publishes, per tick, one
// dressed_human/Crowd message for all of them (the display draws from it) and each human's root
// frame body_<id> on /tf (where navigation and perception code looks people up). Whole skeletons
// on /tf only on request (skeleton_tf): rviz keeps ten minutes of /tf, 49 moving frames a human.

#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "crowd_output.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/model/crowd_walks.h"
#include "tick_clock.h"

namespace dressed_human {

struct CrowdPublisherSettings {
  std::string crowd_file;  // humans, routes, statures (crowd_walks.h); empty: `count` on the default layout
  int count = 6;
  std::string motion_file;  // the walk every human's gait comes from
  std::string gait_file;    // the normative gait table
  std::string body_file;    // the drawn body, whose feet the walks plant (drawn_feet.h)
  double rate = 30.0;       // Hz
  std::string world_frame = "world";
  bool skeleton_tf = false;  // every human's whole skeleton on /tf too
  std::string frame_prefix;  // before every frame name but the world frame (CrowdOutput)

  // Reads the private parameters of `private_node`; throws ParameterError naming the bad one.
  static CrowdPublisherSettings fromParameters(const ros::NodeHandle& private_node);
};

class Parameters;
// ~frame_prefix, checked: TF frame name characters only.
std::string framePrefixParameter(const Parameters& parameters);

// What every crowd walks, whichever way its humans come: the motion (one fitted to a person's
// body is refused: each human walks the robot description's body) and the plain skeleton (a
// suffixed one is refused: the crowd names its humans by id). Throw naming what is wrong.
Motion crowdMotion(const std::string& motion_file);
Skeleton crowdSkeleton(const std::string& urdf);

class CrowdPublisher {
 public:
  // Throws (ParameterError, SkeletonError, MotionError, LocomotionError, CrowdFileError) with a
  // message naming what is wrong.
  CrowdPublisher(ros::NodeHandle node, ros::NodeHandle private_node);

  // Publishes at the configured rate until ROS shuts down (runAtRate).
  void run();

 private:
  struct Member {
    CrowdWalk walk;
    double stature;     // as drawn: 1 when the robot description carries proportions of its own
    Skeleton skeleton;  // suffixed with _<id>, scaled by the stature
    std::unique_ptr<Walker> walker;
    JointAngles angles{};
    SkeletonPose pose;
  };
  void addMember(const CrowdWalk& walk, const Skeleton& plain, const Motion& motion, const NormativeGait& gait,
                 const BodyDescription& body);
  void place();
  void tick();

  CrowdPublisherSettings settings_;
  std::vector<Member> members_;
  std::unique_ptr<CrowdOutput> output_;
  std::vector<CrowdOutput::Human> output_humans_;
  TickClock clock_{"crowd_publisher", "every human starts again"};
};

}  // namespace dressed_human
