// fit_motion: motion capture (BVH, OpenSim .mot/.sto) -> our Fourier motion YAML (SPEC Eq. 1).
// Prints the period, each series' order and residual, and the joint-position error; optionally a
// CSV of accuracy and evaluation cost against the order, for scripts/chart_fourier_order.py.

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/fit_accuracy.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/motion/motion_fit.h"
#include "dressed_human/core/motion/opensim_capture.h"
#include "dressed_human/core/motion/opensim_motion_file.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/foot_sole.h"

namespace dh = dressed_human;

namespace {

constexpr double kRadiansToDegrees = 180.0 / 3.14159265358979323846;

const char* const kUsage =
    "Usage: fit_motion INPUT [options]\n"
    "Fits our skeleton's motion (one Fourier series per DOF, SPEC Eq. 1) to motion capture and\n"
    "writes it as a motion YAML file.\n"
    "\n"
    "INPUT: a BVH file (.bvh) or an OpenSim motion file (.mot, .sto).\n"
    "Options:\n"
    "  -o, --output FILE     write the motion YAML here (default: standard output)\n"
    "  --format bvh|mot      input format (default: from the extension)\n"
    "  --map FILE            joint map YAML (default: built-in CMU, ASF, HumanIK/Mixamo, Unity, Unreal,\n"
    "                        OpenSim body names)\n"
    "  --osim FILE           OpenSim input: the model (OpenSim 4 .osim) the motion is of; its joints give the\n"
    "                        body and the reference (default: config/opensim/gait2392_joints.osim, gait2392)\n"
    "  --urdf FILE           our skeleton (default: urdf/human.urdf)\n"
    "  --body-description FILE  our drawn body, whose feet stand flat where the capture's do\n"
    "                        (default: config/bodies/default.yaml beside the URDF's folder)\n"
    "  --period SECONDS      gait period (default: estimated by autocorrelation; needs two cycles)\n"
    "  --tolerance-deg D     RMS residual every angle series must reach, degrees (default 0.5)\n"
    "  --tolerance-mm MM     RMS residual every root translation series must reach, mm (default 2)\n"
    "  --max-order M         cap on the order m of any series (default 8)\n"
    "  --order M             every series gets exactly order M (no tolerance search)\n"
    "  --skip-frames N       drop N frames at the start (default: auto, drops a leading bind-pose frame)\n"
    "  --name NAME           motion name in the file (default: the input's file name stem)\n"
    "  --body fitted|default fit the person's proportions from the rest pose (BVH) or model (OpenSim) and write them "
    "as\n"
    "                        the motion's body_shape (default: fitted); default: our 1.75 m body\n"
    "  --units U             BVH length unit: m, cm, mm, in, cmu (CMU's ASF units, 1/0.45 in) or\n"
    "                        metres per unit (default: the unit that makes the rest pose a human height)\n"
    "  --sweep-csv FILE      also write accuracy and evaluation cost for m = 1..--sweep-max\n"
    "  --sweep-max M         highest order of the sweep (default 12)\n"
    "  --timing-calls N      MotionEvaluator::evaluate calls timed per order in the sweep (default 200000)\n"
    "  -v, --verbose         also the joint-position error of every joint, the worst joint and frame,\n"
    "                        and mean angles more than 90 degrees from rest\n"
    "  -q, --quiet           no report on standard error\n"
    "  -h, --help            this text\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Arguments {
  std::string input;
  std::string output;
  std::string format;
  std::string map;
  std::string urdf = "urdf/human.urdf";
  std::string body_description;  // "": config/bodies/default.yaml beside the URDF's folder
  std::string osim = "config/opensim/gait2392_joints.osim";
  bool osim_given = false;
  std::string name;
  std::string sweep_csv;
  std::size_t sweep_max = 12;
  std::size_t timing_calls = 200000;
  bool quiet = false;
  bool verbose = false;
  bool fit_body = true;
  bool body_given = false;
  std::string units;
  dh::MotionFitOptions fit;
};

double parseNumber(const std::string& option, const std::string& text, double minimum) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || value < minimum) {
    std::ostringstream message;
    message << option << " expects a number >= " << minimum << ", got '" << text << "'";
    throw UsageError(message.str());
  }
  return value;
}

std::size_t parseCount(const std::string& option, const std::string& text, std::size_t minimum, std::size_t maximum,
                       const std::string& why_maximum) {
  const double value = parseNumber(option, text, static_cast<double>(minimum));
  if (value != std::floor(value)) throw UsageError(option + " expects a whole number, got '" + text + "'");
  if (value > static_cast<double>(maximum)) {
    throw UsageError(option + " is at most " + std::to_string(maximum) + " (" + why_maximum + "), got '" + text + "'");
  }
  return static_cast<std::size_t>(value);
}

double parseNumberWithin(const std::string& option, const std::string& text, double minimum, double maximum,
                         const std::string& unit) {
  const double value = parseNumber(option, text, minimum);
  if (value > maximum) {
    std::ostringstream message;
    message << option << " expects a number in [" << minimum << ", " << maximum << "]" << unit << ", got '" << text
            << "'";
    throw UsageError(message.str());
  }
  return value;
}

// Why `path` cannot be written as a new or replaced file, or "" if it can: said before the fit,
// which takes seconds to minutes, rather than after it.
std::string whyNotWritable(const std::string& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) return "is a directory";
    if (::access(path.c_str(), W_OK) != 0) return std::string("the file is not writable: ") + std::strerror(errno);
    return "";
  }
  const std::size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (::stat(directory.c_str(), &status) != 0) return "no such directory '" + directory + "'";
  if (!S_ISDIR(status.st_mode)) return "'" + directory + "' is not a directory";
  if (::access(directory.c_str(), W_OK) != 0)
    return "the directory '" + directory + "' is not writable: " + std::strerror(errno);
  return "";
}

void requireWritable(const std::string& path, const std::string& what) {
  if (path.empty()) return;
  const std::string why = whyNotWritable(path);
  if (!why.empty()) throw std::runtime_error(path + ": cannot write " + what + ": " + why);
}

std::string stem(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

std::string extension(const std::string& path) {
  const std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  const std::size_t dot = name.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "-o" || arg == "--output") {
      args.output = value();
    } else if (arg == "--format") {
      args.format = value();
      if (args.format != "bvh" && args.format != "mot") throw UsageError("--format must be 'bvh' or 'mot'");
    } else if (arg == "--map") {
      args.map = value();
    } else if (arg == "--osim") {
      args.osim = value();
      args.osim_given = true;
    } else if (arg == "--urdf") {
      args.urdf = value();
    } else if (arg == "--body-description") {
      args.body_description = value();
    } else if (arg == "--period") {
      args.fit.period =
          parseNumberWithin(arg, value(), dh::MotionLimits::kMinPeriod, dh::MotionLimits::kMaxPeriod, " s");
    } else if (arg == "--tolerance-deg") {
      args.fit.tolerance_degrees = parseNumber(arg, value(), 0.0);
    } else if (arg == "--tolerance-mm") {
      args.fit.tolerance_metres = parseNumber(arg, value(), 0.0) / 1000.0;
    } else if (arg == "--max-order") {
      args.fit.max_order =
          parseCount(arg, value(), 1, dh::MotionLimits::kMaxOrder, "more harmonics than a gait capture holds");
    } else if (arg == "--order") {
      args.fit.fixed_order =
          parseCount(arg, value(), 1, dh::MotionLimits::kMaxOrder, "more harmonics than a gait capture holds");
    } else if (arg == "--skip-frames") {
      args.fit.skip_frames = static_cast<int>(parseCount(arg, value(), 0, 1000000, "frames of a capture"));
    } else if (arg == "--name") {
      args.name = value();
    } else if (arg == "--body") {
      const std::string body = value();
      if (body != "fitted" && body != "default")
        throw UsageError("--body must be 'fitted' or 'default', got '" + body + "'");
      args.fit_body = body == "fitted";
      args.body_given = true;
    } else if (arg == "--units") {
      args.units = value();
      dh::unitsByName(args.units);  // a bad unit is a usage error, said before reading anything
    } else if (arg == "--sweep-csv") {
      args.sweep_csv = value();
    } else if (arg == "--sweep-max") {
      args.sweep_max =
          parseCount(arg, value(), 1, dh::MotionLimits::kMaxOrder, "the highest order a motion file may hold");
    } else if (arg == "--timing-calls") {
      args.timing_calls =
          parseCount(arg, value(), 1, 10000000, "each order of the sweep is timed with this many calls");
    } else if (arg == "-v" || arg == "--verbose") {
      args.verbose = true;
    } else if (arg == "-q" || arg == "--quiet") {
      args.quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'");
    } else if (args.input.empty()) {
      args.input = arg;
    } else {
      throw UsageError("more than one input file ('" + args.input + "' and '" + arg + "')");
    }
  }
  if (args.input.empty()) throw UsageError("no input file");
  if (args.format.empty()) {
    const std::string ext = extension(args.input);
    if (ext == "bvh")
      args.format = "bvh";
    else if (ext == "mot" || ext == "sto")
      args.format = "mot";
    else
      throw UsageError("cannot tell the format of '" + args.input + "' from its extension; use --format bvh|mot");
  }
  if (args.osim_given && args.format != "mot") throw UsageError("--osim applies to OpenSim motion input only");
  if (args.format != "bvh") {
    if (!args.units.empty()) throw UsageError("--units applies to BVH input only (OpenSim models are in metres)");
  }
  if (args.name.empty()) args.name = stem(args.input);
  args.fit.name = args.name;
  if (args.body_description.empty()) {  // the package's, beside the URDF's folder
    const std::size_t slash = args.urdf.find_last_of('/');
    args.body_description =
        (slash == std::string::npos ? "." : args.urdf.substr(0, slash)) + "/../config/bodies/default.yaml";
  }
  return args;
}

dh::SampledMotion readCapture(const Arguments& args, const dh::Skeleton& skeleton, bool fit_body) {
  dh::JointMapFile map_file;
  if (!args.map.empty()) map_file = dh::loadJointMapFile(args.map);
  dh::RetargetOptions options;
  options.fit_body = fit_body;
  options.units = args.units;
  options.body =
      std::make_shared<const dh::BodyDescription>(dh::loadBodyDescriptionFile(args.body_description, skeleton));
  if (args.format == "bvh") {
    const dh::BvhClip clip = dh::loadBvhFile(args.input);
    if (!args.map.empty() && map_file.kind != "bvh") {
      throw dh::JointMapError(args.map + ": a BVH input needs a map of kind 'bvh', this one is '" + map_file.kind +
                              "'");
    }
    const dh::BvhJointMap map = args.map.empty() ? dh::chooseBvhJointMap(clip, args.input) : map_file.bvh;
    return dh::retargetBvh(clip, map, skeleton, args.input, options);
  }
  const dh::OpenSimTable table = dh::loadOpenSimMotionFile(args.input);
  if (!args.map.empty() && map_file.kind == "coordinates") {
    // Joint angles only: no model, so no body to fit and no joint positions to measure against.
    if (fit_body && args.body_given) {
      throw dh::JointMapError(
          args.map +
          ": a map of kind 'coordinates' reads joint angles only; --body fitted reads "
          "the body from the model (--osim, with no --map or a map of kind 'bvh' naming its bodies)");
    }
    return dh::retargetCoordinates(table, map_file.coordinates, skeleton, args.input);
  }
  // On its model, the motion is a skeleton capture: bodies as joints, in metres. Without the
  // subject's own model, the generic one is sized to the motion.
  dh::OpenSimModel model = dh::loadOpenSimModelFile(args.osim);
  std::string model_note = "the model " + args.osim;
  if (!args.osim_given) {
    const dh::OpenSimScale scale = dh::estimateOpenSimScale(model, table);
    if (scale.estimated) model = model.scaled(scale.factor);
    model_note = "the generic model " + args.osim + " " + scale.why + " (give the subject's model with --osim)";
  }
  const dh::BvhClip clip = dh::openSimMotionClip(model, table, args.input);
  const dh::BvhJointMap map =
      args.map.empty() ? dh::chooseBvhJointMap(clip, args.input + " on " + args.osim) : map_file.bvh;
  options.units = "m";
  dh::SampledMotion sampled = dh::retargetBvh(clip, map, skeleton, args.input, options);
  sampled.units.reason = "an OpenSim model's; on " + model_note;
  return sampled;
}

std::string commandLine(int argc, char** argv) {
  std::string text = "fit_motion";
  for (int i = 1; i < argc; ++i) text += std::string(" ") + argv[i];
  return text;
}

std::string format(double value, int precision) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(precision) << value;
  return text.str();
}

// Nanoseconds per MotionEvaluator::evaluate call and per evaluate + forward kinematics: the
// fastest of several rounds, since other processes share the machine and only add time.
std::pair<double, double> timeEvaluation(const dh::Motion& motion, const dh::Skeleton& skeleton, std::size_t calls) {
  dh::MotionEvaluator evaluator(motion);
  const dh::ForwardKinematics kinematics(skeleton);
  dh::JointAngles angles{};
  dh::RigidTransform root;
  dh::SkeletonPose pose;
  double checksum = 0.0;
  using Clock = std::chrono::steady_clock;
  constexpr int kRounds = 7;
  const std::size_t per_round = std::max<std::size_t>(1, calls / kRounds);
  double best_evaluate = 1e300;
  double best_with_fk = 1e300;
  for (int round = 0; round < kRounds; ++round) {
    const auto start = Clock::now();
    for (std::size_t i = 0; i < per_round; ++i) {
      evaluator.evaluate(1e-3 * static_cast<double>(i), angles, root);
      checksum += angles[i % dh::kDofCount];
    }
    const auto middle = Clock::now();
    for (std::size_t i = 0; i < per_round; ++i) {
      evaluator.evaluate(1e-3 * static_cast<double>(i), angles, root);
      kinematics.compute(root, angles, pose);
      checksum += pose.bone_in_world[i % dh::kBoneCount].translation.x();
    }
    const auto end = Clock::now();
    best_evaluate = std::min(best_evaluate, std::chrono::duration<double, std::nano>(middle - start).count());
    best_with_fk = std::min(best_with_fk, std::chrono::duration<double, std::nano>(end - middle).count());
  }
  if (!std::isfinite(checksum)) std::cerr << "";  // keeps the loops from being optimised away
  return {best_evaluate / static_cast<double>(per_round), best_with_fk / static_cast<double>(per_round)};
}

// `unfitted`: the same capture on our default body (when the body is fitted), for its columns.
void writeSweep(const Arguments& args, const dh::Skeleton& skeleton, const dh::SampledMotion& sampled,
                const dh::MotionFit& fit, const dh::SampledMotion* unfitted, const dh::MotionFit* unfitted_fit) {
  std::ofstream csv(args.sweep_csv);
  if (!csv) throw std::runtime_error(args.sweep_csv + ": cannot write the sweep CSV");
  csv << "order,mean_rms_deg,max_rms_deg,joint_error_capture_mean_cm,joint_error_capture_max_cm,"
         "joint_error_samples_mean_cm,joint_error_samples_max_cm,root_error_mean_cm,unsmoothed_error_capture_mean_cm,"
         "evaluate_ns,evaluate_fk_ns,body_fitted,default_body_capture_mean_cm,default_body_capture_max_cm,"
         "stance_foot_mean_cm,stance_foot_max_cm\n";
  const std::size_t limit = (fit.times.size() - 1) / 2;
  for (std::size_t order = 1; order <= args.sweep_max; ++order) {
    if (order > limit) break;
    const dh::MotionFit refit = dh::refitWithOrder(fit, order);
    const dh::FitAccuracy accuracy = dh::measureFitAccuracy(skeleton, sampled, refit, refit.motion);
    const auto [evaluate_ns, evaluate_fk_ns] = timeEvaluation(refit.motion, skeleton, args.timing_calls);
    dh::FitAccuracy default_body = accuracy;
    if (unfitted && unfitted_fit) {
      const dh::MotionFit unfitted_refit = dh::refitWithOrder(*unfitted_fit, order);
      default_body = dh::measureFitAccuracy(skeleton, *unfitted, unfitted_refit, unfitted_refit.motion);
    }
    csv << order << ',' << accuracy.mean_rms_degrees << ',' << accuracy.max_rms_degrees << ','
        << accuracy.against_capture.mean_cm << ',' << accuracy.against_capture.max_cm << ','
        << accuracy.against_samples.mean_cm << ',' << accuracy.against_samples.max_cm << ','
        << accuracy.root_translation.mean_cm << ',' << accuracy.unsmoothed_against_capture.mean_cm << ',' << evaluate_ns
        << ',' << evaluate_fk_ns << ',' << (sampled.body_fitted ? 1 : 0) << ',' << default_body.against_capture.mean_cm
        << ',' << default_body.against_capture.max_cm << ',' << accuracy.stance_foot_height.mean_cm << ','
        << accuracy.stance_foot_height.max_cm << '\n';
    if (!args.quiet) {
      std::cerr << "  m=" << order << ": RMS mean " << format(accuracy.mean_rms_degrees, 3) << " deg (max "
                << format(accuracy.max_rms_degrees, 3) << "), joints vs capture "
                << format(accuracy.against_capture.mean_cm, 2) << " cm, vs samples "
                << format(accuracy.against_samples.mean_cm, 3) << " cm, evaluate " << format(evaluate_ns, 1)
                << " ns, +FK " << format(evaluate_fk_ns, 1) << " ns\n";
    }
  }
}

// What the joint-position error is measured against, and the figures, for the report and the file.
std::string accuracyText(const dh::SampledMotion& sampled, const dh::FitAccuracy& accuracy,
                         const std::optional<dh::FitAccuracy>& default_body) {
  if (accuracy.against_capture.samples == 0) {
    return "No capture skeleton (joint coordinates): our default body; joint positions against the capture not "
           "measured.";
  }
  std::ostringstream text;
  if (sampled.body_fitted) {
    text << "Body fitted from the rest pose"
         << (sampled.rest_frame >= 0 ? " (the file's zero pose does not stand: frame " +
                                           std::to_string(sampled.rest_frame + 1) + " is taken as the rest pose)"
                                     : std::string())
         << " (units: " << sampled.units.name << ", " << sampled.units.reason << "; limbs "
         << format(sampled.proportions.overall, 3) << "x ours).\n"
         << "Joint positions vs the capture's own FK (metres, every mapped joint and frame, root-relative): mean "
         << format(accuracy.against_capture.mean_cm, 2) << " cm, max " << format(accuracy.against_capture.max_cm, 2)
         << " cm";
    if (default_body) {
      text << "\n  (on our default body, the capture scaled to our size (stature, or legs without a head): mean "
           << format(default_body->against_capture.mean_cm, 2) << " cm, max "
           << format(default_body->against_capture.max_cm, 2) << " cm)";
    }
    if (accuracy.stance_foot_height.samples > 0) {
      text << "\nOur sole in stance off one floor, as the capture's lowest foot point: mean "
           << format(accuracy.stance_foot_height.mean_cm, 2) << " cm, max "
           << format(accuracy.stance_foot_height.max_cm, 2) << " cm (the capture's floor rises "
           << format(100.0 * sampled.floor_rise_per_second, 2) << " cm/s along the record: levelled)";
    }
  } else {
    text << "Joint positions vs the capture's own FK (scaled to our size: stature, or legs without a head; our default "
            "body, root-relative): mean "
         << format(accuracy.against_capture.mean_cm, 2) << " cm, max " << format(accuracy.against_capture.max_cm, 2)
         << " cm";
  }
  return text.str();
}

// Where the fit is poorest, so that a user can look there: the worst frame and joint of each
// measure, with the joint's fitted and sampled angles there (the middle one, x, is the y-x-z
// split's: near +-90 degrees its other two are ill-defined); and every mean angle a body would
// not hold (over 90 degrees from rest about a twist or side axis).
void reportWorst(const dh::MotionFit& fit, const dh::FitAccuracy& accuracy, std::ostream& out) {
  const auto where = [&](const char* what, const dh::PositionError& e) {
    if (e.samples == 0 || e.worst_joint < 0 || e.worst_frame >= fit.times.size()) return;
    const auto first = static_cast<std::size_t>(e.worst_joint) * dh::kDofsPerJoint;
    out << "  worst " << what << ": " << dh::humanJointNames()[static_cast<std::size_t>(e.worst_joint)] << " at frame "
        << fit.skipped_frames + e.worst_frame << " (" << format(fit.times[e.worst_frame], 3) << " s), "
        << format(e.max_cm, 2) << " cm; its y, x, z there: sampled";
    for (std::size_t d = 0; d < dh::kDofsPerJoint; ++d)
      out << ' ' << format(fit.samples[first + d][e.worst_frame] * kRadiansToDegrees, 1);
    out << " deg, fitted";
    for (std::size_t d = 0; d < dh::kDofsPerJoint; ++d) {
      out << ' '
          << format(fit.motion.series(first + d).valueBySummation(fit.times[e.worst_frame]) * kRadiansToDegrees, 1);
    }
    out << " deg\n";
  };
  where("against the capture", accuracy.against_capture);
  where("against the unsmoothed angles", accuracy.against_samples);
  for (std::size_t i = 0; i < dh::kDofCount; ++i) {
    const dh::SeriesFitReport& r = fit.reports[i];
    const double mean = fit.motion.series(i).a0 / 2.0;
    if (r.driven && r.is_angle && std::abs(mean) > 0.5 * M_PI) {
      out << "  suspect: " << fit.motion.seriesName(i) << " has a mean of " << format(mean * kRadiansToDegrees, 1)
          << " deg, more than 90 from rest\n";
    }
  }
}

void report(const Arguments& args, const dh::SampledMotion& sampled, const dh::MotionFit& fit,
            const dh::FitAccuracy& accuracy, const std::optional<dh::FitAccuracy>& default_body) {
  std::ostream& out = std::cerr;
  out << "fit_motion: " << args.input << ": " << sampled.times.size() << " frames (" << fit.skipped_frames
      << " skipped at the start), period " << format(fit.motion.period, 4) << " s ("
      << (fit.period_estimated ? "autocorrelation peak " + format(fit.period_estimate.correlation, 3) : "given")
      << "), fitted over " << fit.cycles << " whole cycle(s) = " << fit.frames_used << " frames, order cap "
      << fit.max_order_allowed << "\n";
  out << "  forward speed " << format(fit.motion.root.forward_speed, 3) << " m/s\n";
  for (std::size_t i = 0; i < dh::Motion::kSeriesCount; ++i) {
    const dh::SeriesFitReport& r = fit.reports[i];
    out << "  " << std::left << std::setw(24) << fit.motion.seriesName(i) << std::right;
    if (!r.driven) {
      out << " held at rest (not in the source)\n";
      continue;
    }
    out << " m=" << std::setw(2) << r.order << "  RMS "
        << (r.is_angle ? format(r.rms_residual * kRadiansToDegrees, 3) + " deg"
                       : format(r.rms_residual * 1000.0, 2) + " mm")
        << (r.reached_tolerance ? "" : "  (tolerance not reached at the cap)") << "\n";
  }
  out << "  angle RMS residual: mean " << format(accuracy.mean_rms_degrees, 3) << " deg, max "
      << format(accuracy.max_rms_degrees, 3) << " deg\n";
  std::istringstream lines(accuracyText(sampled, accuracy, default_body));
  for (std::string line; std::getline(lines, line);) out << "  " << line << "\n";
  if (args.verbose && accuracy.against_capture.samples > 0) {
    for (std::size_t j = 0; j < dh::kJointCount; ++j) {
      const dh::PositionError& e = accuracy.joint_against_capture[j];
      if (e.samples == 0) continue;
      out << "    " << std::left << std::setw(11) << dh::humanJointNames()[j] << std::right << " mean "
          << format(e.mean_cm, 2) << " cm, max " << format(e.max_cm, 2) << " cm\n";
    }
  }
  if (accuracy.unsmoothed_against_capture.samples > 0) {
    // What no smooth series can beat: a rigid skeleton of ours on every captured frame.
    out << "  our skeleton on the unsmoothed retarget vs the capture's FK: mean "
        << format(accuracy.unsmoothed_against_capture.mean_cm, 2) << " cm, max "
        << format(accuracy.unsmoothed_against_capture.max_cm, 2) << " cm\n";
  }
  if (accuracy.capture_cycle_variation.samples > 0) {
    // What no periodic motion can beat: the capture's cycles differ from one another.
    const dh::PositionError& v = accuracy.capture_cycle_variation;
    out << "  the capture's cycle-to-cycle variation (its joints vs the mean of its " << fit.cycles
        << " cycles at the same phase): mean " << format(v.mean_cm, 2) << " cm, max " << format(v.max_cm, 2) << " cm ("
        << dh::humanJointNames()[static_cast<std::size_t>(v.worst_joint)] << " at frame "
        << fit.skipped_frames + v.worst_frame << ")\n";
  }
  out << "  joint positions, fitted series vs our skeleton on the unsmoothed angles: mean "
      << format(accuracy.against_samples.mean_cm, 3) << " cm, max " << format(accuracy.against_samples.max_cm, 3)
      << " cm; root translation: mean " << format(accuracy.root_translation.mean_cm, 3) << " cm\n";
  if (args.verbose) reportWorst(fit, accuracy, out);
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  try {
    args = parseArguments(argc, argv);
  } catch (const UsageError& error) {
    std::cerr << "fit_motion: " << error.what() << "\n\n" << kUsage;
    return 2;
  }
  try {
    requireWritable(args.output, "the motion file");
    requireWritable(args.sweep_csv, "the sweep CSV");
    const dh::Skeleton skeleton = dh::Skeleton::fromUrdfFile(args.urdf);
    const dh::SampledMotion sampled = readCapture(args, skeleton, args.fit_body);
    dh::MotionFit fit = dh::fitMotion(sampled, args.fit);
    const dh::FitAccuracy accuracy = dh::measureFitAccuracy(skeleton, sampled, fit, fit.motion);
    // The same capture on our default body, for the comparison the report and the file state.
    std::optional<dh::FitAccuracy> default_body;
    std::optional<dh::SampledMotion> unfitted;
    std::optional<dh::MotionFit> unfitted_fit;
    if (sampled.body_fitted) {
      unfitted = readCapture(args, skeleton, false);
      unfitted_fit = dh::fitMotion(*unfitted, args.fit);
      default_body = dh::measureFitAccuracy(skeleton, *unfitted, *unfitted_fit, unfitted_fit->motion);
      fit.motion.body_shape = sampled.proportions.shape;
    }
    if (!args.quiet) report(args, sampled, fit, accuracy, default_body);

    std::map<std::string, std::string> notes;
    std::map<std::string, double> residuals;
    for (std::size_t i = 0; i < dh::Motion::kSeriesCount; ++i) {
      const dh::SeriesFitReport& r = fit.reports[i];
      const std::string name = fit.motion.seriesName(i);
      if (!r.driven) {
        notes[name] = "not in the source: held at rest";
        continue;
      }
      residuals[name] = r.rms_residual;
      notes[name] = "m=" + std::to_string(r.order) + ", RMS " +
                    (r.is_angle ? format(r.rms_residual * kRadiansToDegrees, 3) + " deg"
                                : format(r.rms_residual * 1000.0, 2) + " mm") +
                    (r.reached_tolerance ? "" : " (tolerance not reached)");
    }
    std::ostringstream header;
    header << "Fitted to motion capture by:\n  " << commandLine(argc, argv) << "\n"
           << "Source: " << args.input << " (" << sampled.times.size() << " frames, " << fit.skipped_frames
           << " skipped at the start); period " << format(fit.motion.period, 4) << " s "
           << (fit.period_estimated
                   ? "(estimated: autocorrelation peak " + format(fit.period_estimate.correlation, 3) + ")"
                   : "(given)")
           << ", fitted over " << fit.cycles << " whole cycle(s).\n"
           << "Least-squares Fourier series per DOF (Eq. 1, radians; root translation in metres): order m\n"
           << "the smallest reaching RMS " << args.fit.tolerance_degrees << " deg / "
           << args.fit.tolerance_metres * 1000.0 << " mm, capped at " << fit.max_order_allowed
           << "; rms_residual in radians or metres.\n"
           << accuracyText(sampled, accuracy, default_body) << "\n"
           << "Our skeleton on the fitted series vs on the unsmoothed retarget: mean "
           << format(accuracy.against_samples.mean_cm, 3) << " cm.";
    std::ostringstream text;
    dh::writeMotionYaml(fit.motion, text, header.str(), notes, residuals);
    if (args.output.empty()) {
      std::cout << text.str();
    } else {
      std::ofstream out(args.output);
      if (!out || !(out << text.str())) throw std::runtime_error(args.output + ": cannot write the motion file");
    }
    if (!args.sweep_csv.empty()) {
      writeSweep(args, skeleton, sampled, fit, unfitted ? &*unfitted : nullptr,
                 unfitted_fit ? &*unfitted_fit : nullptr);
    }
  } catch (const std::exception& error) {
    std::cerr << "fit_motion: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
