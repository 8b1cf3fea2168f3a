#include "dressed_human/core/motion/opensim_capture.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "dressed_human/core/motion/mocap_retarget.h"

namespace dressed_human {
namespace {

constexpr std::size_t kChannelsPerJoint = 6;  // X, Y, Z position, then Y, X, Z rotation (decomposeYxz)
constexpr double kRadiansToDegrees = 180.0 / M_PI;

void checkEvenTimes(const OpenSimTable& table, const std::string& source_name) {
  if (table.times.size() < 2) throw OpenSimModelError(source_name + ": fewer than two rows of coordinates");
  const double step = (table.times.back() - table.times.front()) / static_cast<double>(table.times.size() - 1);
  for (std::size_t r = 1; r < table.times.size(); ++r) {
    if (std::abs(table.times[r] - table.times[r - 1] - step) > 0.01 * step) {
      throw OpenSimModelError(source_name + ": rows " + std::to_string(r) + " and " + std::to_string(r + 1) +
                              " are not one even time step apart (" + std::to_string(step) +
                              " s); resample the motion evenly");
    }
  }
}

// The model's coordinate values in one row, in model units.
std::vector<double> rowCoordinates(const OpenSimModel& model, const OpenSimTable& table,
                                   const std::vector<int>& columns, std::size_t row) {
  std::vector<double> values(model.coordinates.size());
  for (std::size_t c = 0; c < values.size(); ++c) {
    const OpenSimCoordinate& coordinate = model.coordinates[c];
    if (columns[c] < 0) {
      values[c] = coordinate.default_value;
      continue;
    }
    const double unit = coordinate.rotational && table.in_degrees ? M_PI / 180.0 : 1.0;
    values[c] = table.rows[row][static_cast<std::size_t>(columns[c])] * unit;
  }
  return values;
}

std::vector<int> tableColumns(const OpenSimModel& model, const OpenSimTable& table) {
  std::vector<int> columns(model.coordinates.size());
  for (std::size_t c = 0; c < columns.size(); ++c) columns[c] = table.findColumn(model.coordinates[c].name);
  return columns;
}

// The lowest body origin's height.
double lowestHeight(const std::vector<Eigen::Isometry3d>& bodies) {
  double lowest = bodies.empty() ? 0.0 : bodies[0].translation().y();
  for (const Eigen::Isometry3d& body : bodies) lowest = std::min(lowest, body.translation().y());
  return lowest;
}

std::string number(double value) {
  std::ostringstream text;
  text << std::setprecision(4) << value;
  return text.str();
}

}  // namespace

OpenSimScale estimateOpenSimScale(const OpenSimModel& model, const OpenSimTable& table) {
  OpenSimScale scale;
  const std::vector<int> columns = tableColumns(model, table);
  bool vertical = false;  // the root body's height is a coordinate the motion has
  for (std::size_t k = 0; !model.joints.empty() && k < 3; ++k) {
    const OpenSimTransformAxis& axis = model.joints[0].translations[k];
    vertical = vertical || (axis.coordinate >= 0 && columns[static_cast<std::size_t>(axis.coordinate)] >= 0 &&
                            std::abs(axis.axis.y()) > 0.99);
  }
  if (!vertical) {
    scale.why = "the motion has no height of its root body; the model is used as it is";
    return scale;
  }
  const double standing = lowestHeight(model.bodyTransforms(model.defaultCoordinates()));
  if (!(standing >= 0.0 && standing <= 0.1)) {
    scale.why = "the model's default pose does not stand on the floor (its lowest joint " + number(standing) +
                " m above y = 0); the model is used as it is";
    return scale;
  }
  const std::size_t rows = table.rows.size();
  std::vector<double> pelvis(rows), drop(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const std::vector<Eigen::Isometry3d> bodies = model.bodyTransforms(rowCoordinates(model, table, columns, r));
    pelvis[r] = bodies[static_cast<std::size_t>(model.joints[0].child_body)].translation().y();
    drop[r] = lowestHeight(bodies) - pelvis[r];
  }
  std::vector<double> factors;
  for (std::size_t r = 1; r + 1 < rows; ++r) {
    const double speed =
        (pelvis[r + 1] + drop[r + 1] - pelvis[r - 1] - drop[r - 1]) / (table.times[r + 1] - table.times[r - 1]);
    if (std::abs(speed) < 0.05 && standing - drop[r] > 0.0) factors.push_back(pelvis[r] / (standing - drop[r]));
  }
  if (factors.size() < 10) {
    scale.why = "fewer than ten frames with a resting foot; the model is used as it is";
    return scale;
  }
  std::nth_element(factors.begin(), factors.begin() + static_cast<std::ptrdiff_t>(factors.size() / 2), factors.end());
  const double factor = factors[factors.size() / 2];
  if (!(factor >= 0.7 && factor <= 1.4)) {
    scale.why = "the pelvis height gives a scale of " + number(factor) +
                ", no person's: the floor is not at y = 0? The model is used as it is";
    return scale;
  }
  scale.factor = factor;
  scale.estimated = true;
  scale.why = "scaled by " + number(factor) +
              " so that the resting feet stand on the floor (y = 0) as in the model's default pose";
  return scale;
}

BvhClip openSimMotionClip(const OpenSimModel& model, const OpenSimTable& table, const std::string& source_name) {
  const std::string where = source_name + " on the model " + (model.name.empty() ? "(unnamed)" : model.name);
  checkEvenTimes(table, source_name);
  const std::vector<int> columns = tableColumns(model, table);
  const bool any = std::any_of(columns.begin(), columns.end(), [](int column) { return column >= 0; });
  if (!any)
    throw OpenSimModelError(where + ": the motion has none of the model's coordinates (a motion of another model?)");

  BvhClip clip;
  std::vector<int> joint_of_body(model.bodies.size(), -1);
  const std::vector<double> zero(model.coordinates.size(), 0.0);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const OpenSimJoint& joint = model.joints[j];
    BvhJoint bvh;
    bvh.name = model.bodies[static_cast<std::size_t>(joint.child_body)];
    bvh.parent = joint.parent_body < 0 ? -1 : joint_of_body[static_cast<std::size_t>(joint.parent_body)];
    if ((bvh.parent < 0) != (j == 0)) {
      throw OpenSimModelError(where + ": joint '" + joint.name + "' joins body '" + bvh.name +
                              "' to the ground too; only one joint may (the root)");
    }
    const Eigen::Isometry3d rest = model.jointTransform(j, zero);
    if (!rest.linear().isIdentity(1e-9)) {
      throw OpenSimModelError(where + ": joint '" + joint.name +
                              "' turns its body in the zero pose (rotated offset frames), which is not read");
    }
    bvh.offset = rest.translation();
    bvh.channels = {BvhChannel::kXposition, BvhChannel::kYposition, BvhChannel::kZposition,
                    BvhChannel::kYrotation, BvhChannel::kXrotation, BvhChannel::kZrotation};
    bvh.first_channel = kChannelsPerJoint * j;
    if (bvh.parent >= 0) clip.joints[static_cast<std::size_t>(bvh.parent)].children.push_back(static_cast<int>(j));
    joint_of_body[static_cast<std::size_t>(joint.child_body)] = static_cast<int>(j);
    clip.joints.push_back(std::move(bvh));
  }
  if (clip.joints.empty()) throw OpenSimModelError(where + ": the model has no joints");
  clip.channel_count = kChannelsPerJoint * clip.joints.size();
  clip.frame_time = (table.times.back() - table.times.front()) / static_cast<double>(table.times.size() - 1);
  clip.frames.resize(table.rows.size());
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<double> q = rowCoordinates(model, table, columns, r);
    std::vector<double>& frame = clip.frames[r];
    frame.resize(clip.channel_count);
    for (std::size_t j = 0; j < clip.joints.size(); ++j) {
      const Eigen::Isometry3d local = model.jointTransform(j, q);
      const Eigen::Vector3d moved = local.translation() - clip.joints[j].offset;
      const Eigen::Vector3d yxz = decomposeYxz(local.linear());
      double* channel = &frame[kChannelsPerJoint * j];
      for (int k = 0; k < 3; ++k) {
        channel[k] = local.translation()[k];  // position channels replace the offset (BvhClip::localTranslation)
        channel[3 + k] = yxz[k] * kRadiansToDegrees;
      }
      if (!moved.allFinite() || !yxz.allFinite() || moved.cwiseAbs().maxCoeff() > 1e4) {
        throw OpenSimModelError(where + ": row " + std::to_string(r + 1) + " puts body '" + clip.joints[j].name +
                                "' out of reach (a coordinate far beyond its range?)");
      }
    }
  }
  return clip;
}

}  // namespace dressed_human
