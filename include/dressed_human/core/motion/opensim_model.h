#pragma once
// The kinematic tree of an OpenSim 4 model (.osim): bodies joined by CustomJoint, PinJoint,
// WeldJoint or PlanarJoint, each joint between a frame on its parent body and one on its child
// body, moved by its coordinates. Enough to compute where the model puts its joints for a row of
// an OpenSim motion (.mot): the capture's own forward kinematics, which the fitted body is read
// from and measured against. Muscles, geometry and mass are not read.
//
// A CustomJoint's SpatialTransform: rotation = R(axis1, f1) R(axis2, f2) R(axis3, f3) (body-fixed,
// in the order listed), then translation = sum of translation axis_i * g_i, in the parent's
// offset frame; each f, g a function of one coordinate: LinearFunction, Constant,
// PolynomialFunction, SimmSpline (the knee's rolling contact) or a MultiplierFunction of one
// (a scaled model's).

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace dressed_human {

struct OpenSimModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// y = f(x) of one coordinate.
struct OpenSimFunction {
  enum class Kind { kConstant, kLinear, kPolynomial, kSpline };
  Kind kind = Kind::kConstant;
  std::vector<double> coefficients;  // constant: {value}; linear: {a, b} (a x + b); polynomial: highest power first
  // SimmSpline: knots and the cubic's coefficients per interval, y + b dx + c dx^2 + d dx^3
  // (Forsythe, Malcolm and Moler's end conditions, as SIMM and OpenSim use); linear beyond the ends.
  std::vector<double> x, y, b, c, d;
  double scale = 1.0;  // a MultiplierFunction's factor

  double value(double argument) const;
};

struct OpenSimTransformAxis {
  int coordinate = -1;  // index into OpenSimModel::coordinates; -1: the function takes no coordinate
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  OpenSimFunction function;
};

struct OpenSimJoint {
  std::string name;
  int parent_body = -1;  // index into OpenSimModel::bodies; -1: ground
  int child_body = -1;
  Eigen::Isometry3d parent_offset = Eigen::Isometry3d::Identity();  // joint frame on the parent body
  Eigen::Isometry3d child_offset = Eigen::Isometry3d::Identity();   // joint frame on the child body
  std::array<OpenSimTransformAxis, 3> rotations;
  std::array<OpenSimTransformAxis, 3> translations;
};

struct OpenSimCoordinate {
  std::string name;
  bool rotational = true;  // radians (degrees in a .mot with inDegrees=yes); else metres
  double default_value = 0.0;
};

struct OpenSimModel {
  std::string name;
  std::vector<std::string> bodies;
  std::vector<OpenSimCoordinate> coordinates;
  std::vector<OpenSimJoint> joints;  // from the ground outwards: a joint's parent body is placed by an earlier one

  int findBody(const std::string& body) const;              // -1 when absent
  int findCoordinate(const std::string& coordinate) const;  // -1 when absent
  // The child body's frame in the parent body's frame, for coordinate values in model units.
  Eigen::Isometry3d jointTransform(std::size_t joint, const std::vector<double>& coordinate_values) const;
  // Every body in the ground's frame.
  std::vector<Eigen::Isometry3d> bodyTransforms(const std::vector<double>& coordinate_values) const;
  std::vector<double> defaultCoordinates() const;
  // The model with every length times `factor` (offset frames, and translations that follow a
  // rotation or are constant, like the knee's), as OpenSim's scale tool does for a uniform
  // factor; translational coordinates (the pelvis's place) are positions, not lengths, and stay.
  OpenSimModel scaled(double factor) const;
};

// Throws OpenSimModelError "source: what" naming the joint, frame or function: not XML, no
// <Model>/<JointSet>, an OpenSim 3 layout (joints inside bodies), a joint type or function it
// does not read, a frame or body that does not exist, a body placed by two joints or by none from
// the ground, spline knots that do not increase, non-finite numbers.
OpenSimModel parseOpenSimModel(const std::string& xml, const std::string& source_name);
OpenSimModel loadOpenSimModelFile(const std::string& path);

}  // namespace dressed_human
