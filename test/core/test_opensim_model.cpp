// OpenSim models: the shipped gait2392 joints read as OpenSim defines them (SIMM splines through
// their knots and exact on cubics, the knee's rolling translation), a motion on its model as a
// BVH clip with the model's own kinematics, the body fitted from it (gait2392 at known scales
// recovered), the fitted walk against the model's FK, and bad models and motions named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <memory>
#include <string>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/motion/fit_accuracy.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/motion/motion_fit.h"
#include "dressed_human/core/motion/opensim_capture.h"
#include "dressed_human/core/motion/opensim_model.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
const std::string kModelPath = kSource + "/config/opensim/gait2392_joints.osim";
const std::string kGaitPath = kSource + "/data/motion/tutorial_normal_gait_cycle.mot";

std::string modelText() {
  std::string text, why;
  EXPECT_TRUE(readWholeFile(kModelPath, text, why)) << why;
  return text;
}

std::size_t jointIndex(const OpenSimModel& model, const std::string& name) {
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    if (model.joints[j].name == name) return j;
  }
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

// Every length of the model times `scale`: offset frames, and the knee's translation splines
// wrapped in the MultiplierFunction a scaled OpenSim model carries.
std::string scaledModel(double scale) {
  std::string text = modelText();
  const std::regex translation("<translation>([^<]*)</translation>");
  std::string scaled;
  auto begin = std::sregex_iterator(text.begin(), text.end(), translation);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    std::istringstream numbers((*it)[1].str());
    double x = 0, y = 0, z = 0;
    numbers >> x >> y >> z;
    std::ostringstream replaced;
    replaced.precision(17);
    replaced << "<translation>" << scale * x << " " << scale * y << " " << scale * z << "</translation>";
    scaled += text.substr(last, static_cast<std::size_t>(it->position()) - last) + replaced.str();
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  scaled += text.substr(last);
  scaled = std::regex_replace(scaled, std::regex("<SimmSpline name=\"function\">"),
                              "<MultiplierFunction name=\"function\"><function><SimmSpline name=\"function\">");
  scaled =
      std::regex_replace(scaled, std::regex("</SimmSpline>"),
                         "</SimmSpline></function><scale>" + std::to_string(scale) + "</scale></MultiplierFunction>");
  return scaled;
}

std::string replaced(const std::string& what, const std::string& with, std::string text = modelText()) {
  const std::size_t at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return text.replace(at, what.size(), with);
}

TEST(OpenSimModel, TheShippedGait2392ReadsAsOpenSimDefinesIt) {
  const OpenSimModel model = loadOpenSimModelFile(kModelPath);
  EXPECT_EQ(model.bodies.size(), 12u);
  ASSERT_EQ(model.joints.size(), 12u);
  EXPECT_EQ(model.joints[0].name, "ground_pelvis");
  EXPECT_EQ(model.joints[0].parent_body, -1);
  EXPECT_EQ(model.coordinates.size(), 23u);
  EXPECT_TRUE(model.coordinates[static_cast<std::size_t>(model.findCoordinate("knee_angle_r"))].rotational);
  EXPECT_FALSE(model.coordinates[static_cast<std::size_t>(model.findCoordinate("pelvis_ty"))].rotational);
  EXPECT_TRUE(model.coordinates[static_cast<std::size_t>(model.findCoordinate("mtp_angle_l"))].rotational);

  std::vector<double> q(model.coordinates.size(), 0.0);
  const Eigen::Isometry3d hip = model.jointTransform(jointIndex(model, "hip_r"), q);
  EXPECT_LT((hip.translation() - Eigen::Vector3d(-0.0707, -0.0661, 0.0835)).norm(), 1e-12);
  // The knee's translation splines pass through their knots (SimmSpline x, y in the model).
  const std::size_t knee = jointIndex(model, "knee_r");
  const auto knee_at = [&](double angle) {
    q[static_cast<std::size_t>(model.findCoordinate("knee_angle_r"))] = angle;
    return model.jointTransform(knee, q);
  };
  EXPECT_NEAR(knee_at(-1.22173).translation().y(), -0.4082, 1e-12);
  EXPECT_NEAR(knee_at(-0.698132).translation().x(), 0.00212, 1e-12);
  EXPECT_NEAR(knee_at(0.0).translation().y(), -0.396, 0.0005);
  // Flexion turns the tibia about the femur's z axis by the coordinate itself.
  const Eigen::AngleAxisd turn(knee_at(-1.0).linear());
  EXPECT_NEAR(turn.angle(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(turn.axis().z()), 1.0, 1e-12);
}

TEST(OpenSimModel, ASimmSplineIsExactOnACubicAndLinearBeyondItsEnds) {
  // Forsythe-Malcolm-Moler end conditions reproduce any cubic; other end conditions do not.
  const auto cubic = [](double x) { return 0.5 * x * x * x - 2.0 * x * x + x - 0.3; };
  OpenSimFunction f;
  f.kind = OpenSimFunction::Kind::kSpline;
  const std::vector<double> knots = {-2.0, -1.3, -0.2, 0.4, 1.5, 2.1};
  std::string xs, ys;
  for (const double x : knots) {
    xs += std::to_string(x) + " ";
    ys += std::to_string(cubic(x)) + " ";
  }
  const std::string xml =
      "<OpenSimDocument><Model name='m'><BodySet><objects><Body name='a'/></objects></BodySet>"
      "<JointSet><objects><CustomJoint name='j'><socket_parent_frame>/ground</socket_parent_frame>"
      "<socket_child_frame>/bodyset/a</socket_child_frame><coordinates><Coordinate name='q'/></coordinates>"
      "<SpatialTransform><TransformAxis name='rotation1'><coordinates>q</coordinates><axis>0 0 1</axis>"
      "<LinearFunction name='function'><coefficients>1 0</coefficients></LinearFunction></TransformAxis>"
      "<TransformAxis name='translation2'><coordinates>q</coordinates><axis>0 1 0</axis>"
      "<SimmSpline name='function'><x>" +
      xs + "</x><y>" + ys +
      "</y></SimmSpline></TransformAxis>"
      "</SpatialTransform></CustomJoint></objects></JointSet></Model></OpenSimDocument>";
  const OpenSimModel model = parseOpenSimModel(xml, "cubic.osim");
  const OpenSimFunction& spline = model.joints[0].translations[1].function;
  for (double x = -2.0; x <= 2.1; x += 0.05) EXPECT_NEAR(spline.value(x), cubic(x), 2e-6) << x;
  // Beyond the ends: the end slope (OpenSim extrapolates linearly).
  const double slope = spline.value(2.1) - spline.value(2.1 - 1e-6);
  EXPECT_NEAR(spline.value(2.6) - spline.value(2.1), 0.5 * slope / 1e-6, 1e-4);
}

TEST(OpenSimCapture, TheClipCarriesTheModelsOwnKinematics) {
  const OpenSimModel model = loadOpenSimModelFile(kModelPath);
  const OpenSimTable table = loadOpenSimMotionFile(kGaitPath);
  const BvhClip clip = openSimMotionClip(model, table, kGaitPath);
  ASSERT_EQ(clip.joints.size(), model.joints.size());
  EXPECT_NEAR(clip.frame_time, 0.02, 1e-12);
  for (const std::size_t row : {0u, 17u, 33u, 50u}) {
    std::vector<double> q(model.coordinates.size(), 0.0);
    for (std::size_t c = 0; c < q.size(); ++c) {
      const int column = table.findColumn(model.coordinates[c].name);
      if (column >= 0)
        q[c] =
            table.rows[row][static_cast<std::size_t>(column)] * (model.coordinates[c].rotational ? M_PI / 180.0 : 1.0);
    }
    const std::vector<Eigen::Isometry3d> world = model.bodyTransforms(q);
    const BvhPose pose = bvhForwardKinematics(clip, row);
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const auto child = static_cast<std::size_t>(model.joints[j].child_body);
      EXPECT_LT((pose.position[j] - world[child].translation()).norm(), 1e-9) << clip.joints[j].name << " row " << row;
      EXPECT_LT((pose.rotation[j] - world[child].linear()).norm(), 1e-9) << clip.joints[j].name << " row " << row;
    }
  }
  // In swing (the left knee flexed most, ~60 degrees) the knee's roll moves the tibia 1 cm down the femur.
  const std::vector<double> knee = table.column(static_cast<std::size_t>(table.findColumn("knee_angle_l")));
  const auto swing = static_cast<std::size_t>(std::min_element(knee.begin(), knee.end()) - knee.begin());
  EXPECT_LT(knee[swing], -55.0);
  const std::size_t tibia = static_cast<std::size_t>(clip.findJoint("tibia_l"));
  EXPECT_LT(clip.localTranslation(swing, tibia).y(), clip.joints[tibia].offset.y() - 0.008);
}

// The walk on its fitted body against the model's FK, as fit_motion measures it.
FitAccuracy fittedWalk(const OpenSimModel& model, const Skeleton& skeleton, SampledMotion& sampled) {
  const OpenSimTable table = loadOpenSimMotionFile(kGaitPath);
  const BvhClip clip = openSimMotionClip(model, table, kGaitPath);
  RetargetOptions options;
  options.fit_body = true;
  options.units = "m";
  options.body = std::make_shared<const BodyDescription>(
      loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton));  // as fit_motion does
  sampled = retargetBvh(clip, chooseBvhJointMap(clip, kGaitPath), skeleton, kGaitPath, options);
  MotionFitOptions fit_options;
  fit_options.period = 1.0;
  fit_options.fixed_order = 6;
  const MotionFit fit = fitMotion(sampled, fit_options);
  return measureFitAccuracy(skeleton, sampled, fit, fit.motion);
}

TEST(OpenSimCapture, TheGaitWalkOnItsFittedBodyMeetsTheModelsJointsAndFeet) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  SampledMotion sampled;
  const FitAccuracy accuracy = fittedWalk(loadOpenSimModelFile(kModelPath), skeleton, sampled);
  EXPECT_TRUE(sampled.body_fitted);
  std::cout << "gait2392 walk, order 6: joints " << accuracy.against_capture.mean_cm << " / "
            << accuracy.against_capture.max_cm << " cm, stance feet " << accuracy.stance_foot_height.mean_cm << " / "
            << accuracy.stance_foot_height.max_cm << " cm\n";
  ASSERT_GT(accuracy.against_capture.samples, 300u);  // 7 joints x 50 frames
  EXPECT_LE(accuracy.against_capture.mean_cm, 2.0);
  EXPECT_LE(accuracy.against_capture.max_cm, 5.0);
  // Our sole stays on one floor while the model stands, within 5 mm on average. At its heel strike
  // ours is up to 2 cm above it for a few frames: the model's heel reaches behind and below its
  // ankle as the foot lands toes up, our drawn foot's heel lies under the ankle (issue 39).
  ASSERT_GT(accuracy.stance_foot_height.samples, 20u);
  EXPECT_LE(accuracy.stance_foot_height.mean_cm, 0.5);
  EXPECT_LE(accuracy.stance_foot_height.max_cm, 2.5);
  EXPECT_LE(accuracy.max_rms_degrees, 6.0);
}

// gait2392 with arms welded to its torso (as the full-body models carry them, but rigid): the
// torso then branches into two arms, and our chest must still point up the middle.
std::string modelWithArms() {
  std::string bodies, joints;
  const auto weld = [&](const std::string& name, const std::string& parent, const std::string& child,
                        const std::string& at) {
    bodies += "<Body name=\"" + child + "\" />";
    joints += "<WeldJoint name=\"" + name + "\"><socket_parent_frame>" + parent +
              "_offset</socket_parent_frame>"
              "<socket_child_frame>/bodyset/" +
              child + "</socket_child_frame><frames><PhysicalOffsetFrame name=\"" + parent +
              "_offset\"><socket_parent>/bodyset/" + parent + "</socket_parent><translation>" + at +
              "</translation><orientation>0 0 0</orientation></PhysicalOffsetFrame></frames></WeldJoint>";
  };
  for (const std::string side : {"r", "l"}) {
    const std::string z = side == "r" ? "0.17" : "-0.17";
    weld("acromial_" + side, "torso", "humerus_" + side, "0.003 0.372 " + z);
    weld("elbow_" + side, "humerus_" + side, "ulna_" + side, "0.013 -0.286 0");
    weld("wrist_" + side, "ulna_" + side, "hand_" + side, "0 -0.24 0");
  }
  std::string text = replaced("<Body name=\"torso\" />", "<Body name=\"torso\" />" + bodies);
  return replaced("</objects>\n    </JointSet>", joints + "</objects>\n    </JointSet>", text);
}

TEST(OpenSimCapture, AModelWithArmsPutsThemWhereItsTorsoCarriesThem) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  const OpenSimModel model = parseOpenSimModel(modelWithArms(), "arms.osim");
  SampledMotion sampled;
  const FitAccuracy accuracy = fittedWalk(model, skeleton, sampled);
  EXPECT_TRUE(sampled.driven[static_cast<std::size_t>(
      skeleton.bone(static_cast<std::size_t>(skeleton.findBone("l_elbow"))).joint)]);
  for (std::size_t j = 0; j < kJointCount; ++j) {
    if (!sampled.driven[j]) continue;
    EXPECT_LE(accuracy.joint_against_capture[j].max_cm, 5.0) << humanJointNames()[j];
  }
  EXPECT_LE(accuracy.against_capture.mean_cm, 2.0);
}

TEST(OpenSimCapture, AModelScaledByAKnownFactorGivesThatBodyWithinOnePercent) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  SampledMotion base;
  fittedWalk(loadOpenSimModelFile(kModelPath), skeleton, base);
  for (const double scale : {0.9, 1.1}) {
    SampledMotion sampled;
    const FitAccuracy accuracy = fittedWalk(parseOpenSimModel(scaledModel(scale), "scaled.osim"), skeleton, sampled);
    for (const char* bone : {"l_hip", "l_knee", "r_hip", "r_knee", "l_ankle", "r_ankle", "l_pelvis", "r_pelvis"}) {
      const auto b = static_cast<std::size_t>(skeleton.findBone(bone));
      EXPECT_NEAR(sampled.proportions.shape.scale[b].z() / base.proportions.shape.scale[b].z(), scale, 0.01 * scale)
          << bone << " at " << scale;
    }
    EXPECT_NEAR(sampled.proportions.overall / base.proportions.overall, scale, 0.01 * scale);
    EXPECT_LE(accuracy.against_capture.max_cm, 5.0 * scale) << scale;
  }
}

// A person of the generic model's shape at `scale`, standing on the floor (y = 0) on the right leg
// while the left swings slowly: what an OpenSim motion of a scaled subject looks like.
OpenSimTable swayingStance(double scale, bool with_height) {
  std::ostringstream text;
  text << "stance\nversion=1\nnRows=60\nnColumns=" << (with_height ? 4 : 3) << "\ninDegrees=yes\nendheader\n"
       << "time\thip_flexion_l\tknee_angle_l" << (with_height ? "\tpelvis_ty" : "") << "\n";
  for (int r = 0; r < 60; ++r) {
    const double t = 0.02 * r;
    text << t << "\t" << 20.0 * std::sin(2.0 * t) << "\t" << -30.0 * (1.0 - std::cos(2.0 * t));
    if (with_height) text << "\t" << 0.95 * scale;
    text << "\n";
  }
  return parseOpenSimMotion(text.str(), "stance.mot");
}

TEST(OpenSimCapture, AGenericModelIsSizedToAMotionOfAScaledSubject) {
  const OpenSimModel model = loadOpenSimModelFile(kModelPath);
  for (const double scale : {0.9, 1.1}) {
    const OpenSimScale estimate = estimateOpenSimScale(model, swayingStance(scale, true));
    EXPECT_TRUE(estimate.estimated) << estimate.why;
    EXPECT_NEAR(estimate.factor, scale, 0.01 * scale) << estimate.why;
    // The scaled model stands the motion's feet on the floor again.
    const OpenSimModel sized = model.scaled(estimate.factor);
    std::vector<double> q = sized.defaultCoordinates();
    q[static_cast<std::size_t>(sized.findCoordinate("pelvis_ty"))] = 0.95 * scale;
    double lowest = 1.0;
    for (const Eigen::Isometry3d& body : sized.bodyTransforms(q)) lowest = std::min(lowest, body.translation().y());
    EXPECT_NEAR(lowest, 0.016 * scale, 0.005);  // 1 % of the 0.93 m from pelvis to foot is 9 mm
  }
  const OpenSimScale without_height = estimateOpenSimScale(model, swayingStance(1.1, false));
  EXPECT_FALSE(without_height.estimated);
  EXPECT_EQ(without_height.factor, 1.0);
  EXPECT_NE(without_height.why.find("no height of its root body"), std::string::npos) << without_height.why;
  const OpenSimScale floating = estimateOpenSimScale(model, swayingStance(1.6, true));
  EXPECT_FALSE(floating.estimated);
  EXPECT_NE(floating.why.find("the floor is not at y = 0?"), std::string::npos) << floating.why;
}

void expectModelError(const std::string& xml, const std::string& message) {
  try {
    parseOpenSimModel(xml, "bad.osim");
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const OpenSimModelError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("bad.osim: ", 0), 0u) << error.what();
    EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
  }
}

// The first element `name` of the model renamed `other`, its closing tag too.
std::string renamedElement(const std::string& open, const std::string& name, const std::string& other) {
  std::string text = modelText();
  const std::size_t at = text.find(open);
  EXPECT_NE(at, std::string::npos) << open;
  const std::size_t close = text.find("</" + name + ">", at);
  text.replace(close, name.size() + 3, "</" + other + ">");
  return text.replace(at + 1, name.size(), other);
}

TEST(OpenSimModel, BadModelsAreRefusedByName) {
  expectModelError("<Model", "not valid XML");
  expectModelError("<robot/>", "no <Model> element");
  expectModelError(
      "<OpenSimDocument><Model><BodySet><objects><Body "
      "name='femur'><Joint/></Body></objects></BodySet></Model></OpenSimDocument>",
      "body 'femur' holds its joint: an OpenSim 3 model");
  expectModelError(renamedElement("<CustomJoint name=\"mtp_r\">", "CustomJoint", "BallJoint"),
                   "joint 'mtp_r' (BallJoint): this joint type is not read");
  expectModelError(renamedElement("<SimmSpline name=\"function\">", "SimmSpline", "GCVSpline"),
                   "joint 'knee_r' (CustomJoint) translation1 uses a GCVSpline, which is not read");
  expectModelError(replaced("<x> -2.0944 -1.74533", "<x> -2.0944 -2.74533"),
                   "joint 'knee_r' (CustomJoint) translation1 SimmSpline x must increase, it does not at knot 2");
  expectModelError(
      replaced("<socket_parent>/bodyset/femur_r</socket_parent>", "<socket_parent>/bodyset/thigh_r</socket_parent>"),
      "names '/bodyset/thigh_r', which is no body of the model");
  expectModelError(
      replaced("<translation>0 -0.42999999999999999 0</translation>", "<translation>0 nan 0</translation>"),
      "translation must be three finite numbers, got '0 nan 0'");
  expectModelError(replaced("<Body name=\"torso\" />", "<Body name=\"torso\" /><Body name=\"head\" />"),
                   "body 'head' is joined to the ground by no chain of joints");
  expectModelError(
      replaced("<translation>0 -0.42999999999999999 0</translation>", "<translation>0 -4300 0</translation>"),
      "translation '0 -4300 0' is beyond 1000");
  expectModelError(
      replaced("<y> -0.0032 0.00179", "<y> -1000 1000", replaced("<x> -2.0944 -1.74533", "<x> -2.0944 -2.094399999")),
      "joint 'knee_r' (CustomJoint) translation1 SimmSpline knots are too close for a spline through them");
  expectModelError(replaced("<socket_child_frame>talus_l_offset</socket_child_frame>",
                            "<socket_child_frame>/bodyset/talus_r</socket_child_frame>"),
                   "body 'talus_r' is the child of two joints ('ankle_r', 'ankle_l')");
  expectModelError(
      replaced("<coordinates>knee_angle_r</coordinates>", "<coordinates>knee_angle_r hip_flexion_r</coordinates>"),
      "depends on several coordinates (knee_angle_r hip_flexion_r), which is not read");
  EXPECT_THROW(loadOpenSimModelFile(kSource + "/no/such/model.osim"), OpenSimModelError);
}

TEST(OpenSimCapture, MotionsThatDoNotFitTheModelAreRefusedByName) {
  const OpenSimModel model = loadOpenSimModelFile(kModelPath);
  const std::string header = "other\nversion=1\nnRows=3\nnColumns=2\ninDegrees=yes\nendheader\n";
  const auto refused = [&](const std::string& text, const std::string& message) {
    try {
      openSimMotionClip(model, parseOpenSimMotion(text, "bad.mot"), "bad.mot");
      ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const OpenSimModelError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
  };
  refused(header + "time\tshoulder_flex\n0\t1\n0.1\t2\n0.2\t3\n", "has none of the model's coordinates");
  refused(header + "time\tknee_angle_r\n0\t1\n0.1\t2\n0.35\t3\n", "rows 1 and 2 are not one even time step apart");
  // A knee bent 1e9 degrees puts the tibia, through its translation splines, 100 km away.
  refused(header + "time\tknee_angle_r\n0\t1\n0.1\t1e9\n0.2\t3\n", "row 2 puts body 'tibia_r' out of reach");
}

}  // namespace
}  // namespace dressed_human
