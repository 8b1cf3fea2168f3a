// Writes the CSVs behind docs/stability/*.png (issue #8: stability where methods fail), one file
// per case: stability_cases SOURCE_DIRECTORY OUTPUT_DIRECTORY (the source directory holds urdf/
// and config/). scripts/make_stability_figures.py runs
// it and draws the figures; docs/stability.md explains them.
//
//   buckling_domain.csv   alpha, h1, w, h2 of Y patterns across alpha_min under each policy
//   fk_gimbal.csv         bone end through x = +-90 degrees, and a rotation path through gimbal
//                         lock split into y, x, z (the split jumps, its composition does not)
//   fk_wrap.csv           bone end across the +-pi seam, and the FK error against 2 pi k turns
//   skirt_map.csv         A_i, A_j (corrected and printed) and the garment's hem height vs c
//   period.csv            autocorrelation of periodic and non-periodic input, with the verdict
//   corner_normals.csv    angle between n(t, t) and the degenerate corner's normal vs t
//   relief_<case>.csv     height maps of the Voronoi relief with degenerate seed sets
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/relief/buckling_solution.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/gait_period.h"
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/relief/skin_relief.h"
#include "dressed_human/core/garments/skirt_length_map.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace dressed_human;

namespace {

std::string kSource;  // the package's source directory (urdf/, config/), from the command line

class Csv {
 public:
  Csv(const std::string& directory, const std::string& name, const std::string& header)
      : file_(std::fopen((directory + "/" + name).c_str(), "w")) {
    if (file_ == nullptr) throw std::runtime_error("cannot write " + directory + "/" + name);
    std::fprintf(file_, "%s\n", header.c_str());
  }
  ~Csv() { std::fclose(file_); }
  Csv(const Csv&) = delete;
  Csv& operator=(const Csv&) = delete;
  void row(const std::vector<double>& values, const std::string& tail = "") {
    for (std::size_t i = 0; i < values.size(); ++i) std::fprintf(file_, i ? ",%.17g" : "%.17g", values[i]);
    if (!tail.empty()) std::fprintf(file_, ",%s", tail.c_str());
    std::fprintf(file_, "\n");
  }

 private:
  std::FILE* file_;
};

void bucklingDomain(const std::string& out) {
  Csv csv(out, "buckling_domain.csv", "alpha,alpha_min,policy,h1,w,h2,bend_angle");
  const BucklingCell cell{0.5, 1.0};
  const double alpha_min = minimumAlphaForSplitPatterns(cell);
  const OutOfDomainPolicy policies[] = {OutOfDomainPolicy::clampToDomainEdge, OutOfDomainPolicy::fallBackToIPattern,
                                        OutOfDomainPolicy::throwError};
  for (int k = 0; k <= 1000; ++k) {
    const double alpha = k / 1000.0;
    for (int p = 0; p < 3; ++p) {
      double h1 = std::nan(""), w = std::nan(""), h2 = std::nan(""), bend = std::nan("");
      try {
        const BucklingSolution s = solveBuckling(PatternKind::Y, alpha, cell, policies[p]);
        h1 = s.h1;
        w = s.w;
        h2 = s.h2;
        bend = s.bend_angle;
      } catch (const std::domain_error&) {
        // throwError beyond the edge: a gap in the curve.
      }
      csv.row({alpha, alpha_min, static_cast<double>(p), h1, w, h2, bend});
    }
  }
}

Eigen::Matrix3d yxz(double y, double x, double z) {
  return (Eigen::AngleAxisd(y, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(x, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(z, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

void fkGimbal(const std::string& out, const Skeleton& skeleton) {
  Csv csv(out, "fk_gimbal.csv", "kind,s,x_angle,end_x,end_y,end_z,split_y,split_x,split_z,reconstruction_error");
  const ForwardKinematics fk(skeleton);
  const std::size_t bone = static_cast<std::size_t>(skeleton.findBone("l_shoulder"));
  const std::size_t first = static_cast<std::size_t>(skeleton.bone(bone).joint) * kDofsPerJoint;
  JointAngles angles{};
  angles[first] = 0.4;
  angles[first + 2] = -0.7;
  SkeletonPose pose;
  for (int k = 0; k <= 720; ++k) {
    angles[first + 1] = -M_PI + 2.0 * M_PI * k / 720.0;
    fk.compute(RigidTransform(), angles, pose);
    const RigidTransform& frame = pose.bone_in_world[bone];
    const Eigen::Vector3d end = frame.translation + frame.rotation * Eigen::Vector3d(0, 0, skeleton.bone(bone).length);
    csv.row({0.0, k / 720.0, angles[first + 1], end.x(), end.y(), end.z(), 0, 0, 0, 0});
  }
  // A rotation path whose x passes 90 degrees: the split that retargeting stores.
  for (int k = 0; k <= 2000; ++k) {
    const double s = k / 2000.0;
    const double x = M_PI / 2 - 0.3 + 0.6 * s;
    const Eigen::Matrix3d r = yxz(0.5 + 0.2 * s, x, 0.4 - 0.5 * s);
    const Eigen::Vector3d split = decomposeYxz(r);
    const double error = (yxz(split[0], split[1], split[2]) - r).norm();
    csv.row({1.0, s, x, 0, 0, 0, split[0], split[1], split[2], error});
  }
}

void fkWrap(const std::string& out, const Skeleton& skeleton) {
  Csv csv(out, "fk_wrap.csv", "kind,angle_or_turns,end_x,end_y,end_z,error");
  const ForwardKinematics fk(skeleton);
  const std::size_t bone = static_cast<std::size_t>(skeleton.findBone("l_knee"));
  const std::size_t first = static_cast<std::size_t>(skeleton.bone(bone).joint) * kDofsPerJoint;
  const auto end = [&](const JointAngles& angles) {
    SkeletonPose pose;
    fk.compute(RigidTransform(), angles, pose);
    const RigidTransform& frame = pose.bone_in_world[bone];
    return Eigen::Vector3d(frame.translation + frame.rotation * Eigen::Vector3d(0, 0, skeleton.bone(bone).length));
  };
  // Knee flexion written as wrapped angles in (-pi, pi] while it turns through pi.
  for (int k = 0; k <= 400; ++k) {
    const double unwrapped = M_PI - 0.5 + 1.0 * k / 400.0;
    JointAngles angles{};
    angles[first] = std::remainder(unwrapped, 2.0 * M_PI);
    const Eigen::Vector3d e = end(angles);
    csv.row({0.0, angles[first], e.x(), e.y(), e.z(), 0.0});
  }
  JointAngles base{};
  for (std::size_t i = 0; i < kDofCount; ++i) base[i] = 0.3 * std::sin(1.7 * static_cast<double>(i) + 0.2);
  SkeletonPose reference, shifted_pose;
  fk.compute(RigidTransform(), base, reference);
  for (int e = 0; e <= 12; ++e) {
    const double turns = std::pow(10.0, e);
    JointAngles shifted = base;
    for (double& a : shifted) a += 2.0 * M_PI * turns;
    fk.compute(RigidTransform(), shifted, shifted_pose);
    double worst = 0.0;
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      worst =
          std::max(worst, (shifted_pose.bone_in_world[b].translation - reference.bone_in_world[b].translation).norm());
    }
    csv.row({1.0, turns, 0, 0, 0, worst});
  }
}

void skirtMap(const std::string& out, const Skeleton& skeleton) {
  Csv csv(out, "skirt_map.csv", "c,c_k,a_i,a_j,printed_a_j,hem_z");
  const BodyDescription body = loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton);
  GarmentDescription description = loadGarmentFile(kSource + "/config/garments/skirt.yaml", skeleton);
  description.legs.at_knee = false;
  const Garment knee(description, skeleton, body.shape);
  const ForwardKinematics fk(skeleton, body.shape);
  const double ck = knee.kneeLength();
  // The weights depend on d_i / (d_i + d_j) only.
  const double di = ck, dj = 1.0 - ck;
  JointAngles zero{};
  RigidTransform root;
  root.translation.z() = 1.0;
  SkeletonPose rest;
  fk.compute(root, zero, rest);
  for (int k = 0; k <= 400; ++k) {
    const double c = k / 400.0;
    const SkirtLengthWeights w = skirtLengthWeights(c, di, dj);
    description.legs.length = c;
    Garment skirt(description, skeleton, body.shape);
    skirt.pose(rest);
    double hem = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : skirt.net().worldPoints()) hem = std::min(hem, p.z());
    csv.row({c, ck, w.ai, w.aj, printedLowerWeight(c, di, dj), hem});
  }
}

std::vector<double> autocorrelation(const std::vector<std::vector<double>>& channels, std::size_t max_lag) {
  // Same definition as gait_period.h (straight line removed, pooled, normalised over the overlap),
  // recomputed here because the library refuses to return it for input without a period.
  std::vector<std::vector<double>> detrended;
  for (const std::vector<double>& channel : channels) {
    const double n = static_cast<double>(channel.size());
    double mi = 0, mv = 0;
    for (std::size_t i = 0; i < channel.size(); ++i) {
      mi += static_cast<double>(i) / n;
      mv += channel[i] / n;
    }
    double cov = 0, var = 0;
    for (std::size_t i = 0; i < channel.size(); ++i) {
      cov += (static_cast<double>(i) - mi) * (channel[i] - mv);
      var += (static_cast<double>(i) - mi) * (static_cast<double>(i) - mi);
    }
    std::vector<double> r(channel.size());
    for (std::size_t i = 0; i < channel.size(); ++i) r[i] = channel[i] - mv - cov / var * (static_cast<double>(i) - mi);
    detrended.push_back(r);
  }
  std::vector<double> out(max_lag + 1, 0.0);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) {
    double p = 0, h = 0, t = 0;
    for (const std::vector<double>& x : detrended) {
      for (std::size_t i = 0; i + lag < x.size(); ++i) {
        p += x[i] * x[i + lag];
        h += x[i] * x[i];
        t += x[i + lag] * x[i + lag];
      }
    }
    out[lag] = h > 0 && t > 0 ? p / std::sqrt(h * t) : 0.0;
  }
  return out;
}

void period(const std::string& out) {
  Csv csv(out, "period.csv", "signal,lag_seconds,r,found_period,name,verdict");
  const std::size_t frames = 600;
  const double frame_time = 0.01;
  std::vector<std::vector<double>> gait(2, std::vector<double>(frames)), walk(3, std::vector<double>(frames)),
      chirp(1, std::vector<double>(frames)), ramp(1, std::vector<double>(frames));
  std::mt19937 random(3);
  std::normal_distribution<double> increment(0.0, 1.0);
  for (auto& channel : walk) {
    double value = 0.0;
    for (double& v : channel) v = value += increment(random);
  }
  std::normal_distribution<double> noise(0.0, 0.02);
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = static_cast<double>(i) * frame_time;
    gait[0][i] = 0.5 * std::sin(2 * M_PI * t / 1.1) + 0.1 * std::sin(4 * M_PI * t / 1.1 + 0.3) + noise(random);
    gait[1][i] = 0.5 * std::sin(2 * M_PI * t / 1.1 + M_PI) + 0.1 * std::sin(4 * M_PI * t / 1.1 + 0.3) + noise(random);
    const double s = static_cast<double>(i) / frames;
    chirp[0][i] = std::sin(2 * M_PI * (1.0 * s + 1.5 * s * s) * 3.0);
    ramp[0][i] = 0.8 * t + noise(random);
  }
  const std::vector<std::pair<std::string, std::vector<std::vector<double>>>> signals = {
      {"gait (period 1.1 s)", gait}, {"random walk", walk}, {"chirp", chirp}, {"ramp + noise", ramp}};
  for (std::size_t k = 0; k < signals.size(); ++k) {
    const auto& [name, channels] = signals[k];
    std::string verdict;
    double found = std::nan("");
    try {
      found = estimateGaitPeriod(channels, frame_time).period;
      verdict = "period found";
    } catch (const MotionError& error) {
      verdict = error.what();
      verdict = verdict.substr(0, verdict.find(':'));
    }
    const std::vector<double> r = autocorrelation(channels, frames / 2);
    for (std::size_t lag = 0; lag < r.size(); ++lag) {
      csv.row({static_cast<double>(k), static_cast<double>(lag) * frame_time, r[lag], found}, name + "," + verdict);
    }
  }
}

void cornerNormals(const std::string& out) {
  Csv csv(out, "corner_normals.csv", "case,t,angle");
  BezierPatch::ControlPoints base;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const double x = i / 3.0, y = j / 3.0;
      base[BezierPatch::index(i, j)] = {x, y, 0.3 * x * y - 0.2 * x * x + 0.1 * y};
    }
  }
  for (int c = 0; c < 4; ++c) {
    BezierPatch::ControlPoints p = base;
    if (c == 0) p[BezierPatch::index(1, 0)] = p[0];
    if (c == 1) p[BezierPatch::index(0, 1)] = p[0] + 0.6 * (p[BezierPatch::index(1, 0)] - p[0]);
    if (c == 2) {
      for (int i = 1; i < 4; ++i) p[BezierPatch::index(i, 0)] = p[0];
    }
    if (c == 3) {
      for (int i = 1; i < 4; ++i) p[BezierPatch::index(i, 0)] = p[0];
      for (int j = 1; j < 4; ++j) p[BezierPatch::index(0, j)] = p[0];
    }
    const BezierPatch patch(p);
    const Eigen::Vector3d corner = patch.normal(0.0, 0.0);
    for (int k = 0; k <= 140; ++k) {
      const double t = std::pow(10.0, -k / 10.0);
      const Eigen::Vector3d n = patch.normal(t, t);
      csv.row({static_cast<double>(c), t, std::atan2(n.cross(corner).norm(), n.dot(corner))});
    }
  }
}

void relief(const std::string& out) {
  struct Case {
    const char* name;
    SkinReliefParameters parameters;
  };
  // Each case: the defaults with a few parameters pushed to where the construction degenerates.
  const auto skin = [](auto&& change) {
    SkinReliefParameters parameters;
    change(parameters);
    return parameters;
  };
  const std::vector<Case> cases = {
      {"cocircular", skin([](SkinReliefParameters& p) {
         p.jitter = 0.0;
         p.wobble = 0.0;
       })},
      {"max_jitter", skin([](SkinReliefParameters& p) {
         p.jitter = 0.5;
         p.levels = 2;
       })},
      {"collinear", skin([](SkinReliefParameters& p) {
         p.cell_size = 0.1;
         p.direction_stretch = 10.0;
         p.direction_angle = M_PI / 2;
         p.jitter = 0.0;
         p.wobble = 0.0;
       })},
      {"one_column", skin([](SkinReliefParameters& p) {
         p.cell_size = 1.0;
         p.jitter = 0.5;
         p.levels = 2;
       })},
  };
  for (const Case& c : cases) {
    const SkinRelief relief(c.parameters);
    // The brute-force reference path: the figure shows the model, not an accelerated lookup.
    const ReliefMap map = relief.renderBruteForce(128, 128);
    Csv csv(out, std::string("relief_") + c.name + ".csv", "heights of one row per line, 128 x 128");
    for (int row = 0; row < map.height; ++row) {
      std::vector<double> values;
      for (int column = 0; column < map.width; ++column) values.push_back(map.heights[map.index(column, row)]);
      csv.row(values);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SOURCE_DIRECTORY OUTPUT_DIRECTORY\n", argv[0]);
    return 2;
  }
  kSource = argv[1];
  const std::string out = argv[2];
  try {
    const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
    bucklingDomain(out);
    fkGimbal(out, skeleton);
    fkWrap(out, skeleton);
    skirtMap(out, skeleton);
    period(out);
    cornerNormals(out);
    relief(out);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "stability_cases: %s\n", error.what());
    return 1;
  }
  return 0;
}
