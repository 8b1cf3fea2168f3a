// The walk against speed (issue 20): per speed our stride with planted feet and cadence against
// the normative trend (Schwartz et al. 2008 scaled to our leg), and the worst stance slide per
// step with planted feet and with the old playback (the fitted walk sped up, root moving at a
// constant speed). scripts/chart_walk_speed.py draws docs/walk_speed.png from the two CSV files.
//
// Usage: walk_speed_table <source_directory> <output_directory>
#include <algorithm>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/locomotion/foot_contact.h"
#include "dressed_human/core/locomotion/stance_slide.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

namespace {

using namespace dressed_human;

constexpr double kStep = 0.01;     // s, the node's default 100 Hz
constexpr double kSettle = 3.0;    // s before measuring
constexpr double kMeasure = 10.0;  // s measured

// Planted: a Walker driven straight at `speed`; its feet's contact with the ground in `contact`.
double plantedSlide(const Skeleton& skeleton, const SpeedGait& gait, double speed, double& travelled_speed,
                    double& lowest, FootContactMeter& contact) {
  Walker walker(skeleton, BodyShape(), gait);
  walker.place({0.0, 0.0}, 0.0);
  walker.drive(speed, 0.0);
  JointAngles angles;
  SkeletonPose pose;
  StanceSlideMeter meter;
  double start = 0.0;
  for (int i = 0; i < static_cast<int>((kSettle + kMeasure) / kStep); ++i) {
    walker.step(kStep, angles, pose);
    if (i == static_cast<int>(kSettle / kStep)) start = walker.position().x();
    if (i >= static_cast<int>(kSettle / kStep)) {
      meter.add(walker.feet(), pose);
      contact.add(walker.feet().soles(), pose);
    }
  }
  travelled_speed = (walker.position().x() - start) / kMeasure;
  lowest = meter.lowest;
  return meter.worstSlide();
}

// The old playback: the fitted walk at speed_factor = speed / its own speed, root x = speed t,
// set down so that its lowest sole point over the measure touches the floor: the fitted root
// height need not put the drawn sole there, and a sole that never comes down shows no slide.
double playbackSlide(const Skeleton& skeleton, const Motion& walk, const FootSoles& soles, double speed,
                     double& lowest) {
  MotionEvaluator evaluator(walk);
  ForwardKinematics kinematics(skeleton);
  PlantedFeet feet(soles);
  const double factor = speed / walk.root.forward_speed;
  JointAngles angles;
  RigidTransform root;
  SkeletonPose pose;
  const int first = static_cast<int>(kSettle / kStep), end = static_cast<int>((kSettle + kMeasure) / kStep);
  double floor = std::numeric_limits<double>::infinity();
  for (int i = first; i < end; ++i) {
    evaluator.evaluate(i * kStep * factor, angles, root);
    kinematics.compute(root, angles, pose);
    for (std::size_t side = 0; side < 2; ++side) floor = std::min(floor, soles.lowest(pose, side));
  }
  StanceSlideMeter meter;
  for (int i = first; i < end; ++i) {
    evaluator.evaluate(i * kStep * factor, angles, root);
    root.translation.z() -= floor;
    kinematics.compute(root, angles, pose);
    meter.add(feet, pose);
  }
  lowest = meter.lowest;
  return meter.worstSlide();
}

int run(const std::string& source, const std::string& output) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
  const Motion walk = loadMotionFile(source + "/config/motions/walk.yaml");
  const BodyDescription body = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
  const SpeedGait gait(walk, loadNormativeGaitFile(source + "/config/gait/speed_gaits.yaml"), skeleton, BodyShape(),
                       FootSoles(skeleton, BodyShape(), body));

  std::ofstream trend(output + "/walk_speed_trend.csv");
  trend << "speed_m_s,our_stride_m,our_cadence_steps_min,normative_stride_m,normative_cadence_steps_min\n";
  for (const SpeedGait::Knot& knot : gait.knots()) {
    trend << knot.speed << ',' << knot.stride << ',' << 120.0 * knot.cycle_rate << ',' << knot.normative_stride << ','
          << 60.0 * knot.normative_cadence << '\n';
  }
  std::ofstream slides(output + "/walk_slide.csv");
  slides << "speed_m_s,planted_worst_slide_mm,playback_worst_slide_mm,planted_travel_m_s,planted_lowest_sole_mm,"
            "playback_lowest_sole_mm,stance_percent,flat_percent_of_stance,heel_first_percent,stance_left_percent,"
            "stance_right_percent\n";
  for (double speed = 0.6; speed <= 1.81; speed += 0.2) {
    double travelled = 0.0, planted_lowest = 0.0, playback_lowest = 0.0;
    FootContactMeter contact;
    const double planted = plantedSlide(skeleton, gait, speed, travelled, planted_lowest, contact);
    const double playback = playbackSlide(skeleton, walk, gait.soles(), speed, playback_lowest);
    slides << speed << ',' << planted * 1e3 << ',' << playback * 1e3 << ',' << travelled << ',' << planted_lowest * 1e3
           << ',' << playback_lowest * 1e3 << ',' << 50.0 * (contact.stanceShare(0) + contact.stanceShare(1)) << ','
           << 50.0 * (contact.flatShareOfStance(0) + contact.flatShareOfStance(1)) << ','
           << 100.0 * static_cast<double>(contact.heelFirstStances(0) + contact.heelFirstStances(1)) /
                  static_cast<double>(std::max<std::size_t>(1, contact.stances(0) + contact.stances(1)))
           << ',' << 100.0 * contact.stanceShare(0) << ',' << 100.0 * contact.stanceShare(1) << '\n';
  }
  std::cout << "wrote " << output << "/walk_speed_trend.csv and walk_slide.csv\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: walk_speed_table <source_directory> <output_directory>\n";
    return 2;
  }
  try {
    return run(argv[1], argv[2]);
  } catch (const std::exception& error) {
    std::cerr << "walk_speed_table: " << error.what() << '\n';
    return 1;
  }
}
