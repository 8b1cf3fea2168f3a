#include "dressed_human/core/motion/opensim_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <tinyxml2.h>

#include "dressed_human/core/io/text_file.h"

namespace dressed_human {
namespace {

using tinyxml2::XMLElement;

// Lengths (m), angles (rad) and function values beyond this are no person's model: refused, so
// that nothing downstream overflows.
constexpr double kMaxNumber = 1000.0;
constexpr const char* kMaxNumberText = "1000";

std::vector<double> numbers(const XMLElement* element) {
  std::vector<double> values;
  if (!element || !element->GetText()) return values;
  std::istringstream text(element->GetText());
  std::string word;
  while (text >> word) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size() || !std::isfinite(value)) return {std::nan("")};
    values.push_back(value);
  }
  return values;
}

std::string words(const XMLElement* element) {
  std::istringstream text(element && element->GetText() ? element->GetText() : "");
  std::string all, word;
  while (text >> word) all += (all.empty() ? "" : " ") + word;
  return all;
}

// The cubic spline through the knots with Forsythe, Malcolm and Moler's end conditions (the third
// derivative at each end that of the cubic through the four end knots), SIMM's and OpenSim's.
void fitSimmSpline(OpenSimFunction& f) {
  const std::size_t n = f.x.size();
  std::vector<double>& b = f.b;
  std::vector<double>& c = f.c;
  std::vector<double>& d = f.d;
  b.assign(n, 0.0);
  c.assign(n, 0.0);
  d.assign(n, 0.0);
  const std::vector<double>& x = f.x;
  const std::vector<double>& y = f.y;
  if (n < 3) {
    b[0] = b[n - 1] = n == 2 ? (y[1] - y[0]) / (x[1] - x[0]) : 0.0;
    return;
  }
  const std::size_t last = n - 1;
  d[0] = x[1] - x[0];
  c[1] = (y[1] - y[0]) / d[0];
  for (std::size_t i = 1; i < last; ++i) {
    d[i] = x[i + 1] - x[i];
    b[i] = 2.0 * (d[i - 1] + d[i]);
    c[i + 1] = (y[i + 1] - y[i]) / d[i];
    c[i] = c[i + 1] - c[i];
  }
  b[0] = -d[0];
  b[last] = -d[last - 1];
  c[0] = 0.0;
  c[last] = 0.0;
  if (n > 3) {
    c[0] = c[2] / (x[3] - x[1]) - c[1] / (x[2] - x[0]);
    c[last] = c[last - 1] / (x[last] - x[last - 2]) - c[last - 2] / (x[last - 1] - x[last - 3]);
    c[0] = c[0] * d[0] * d[0] / (x[3] - x[0]);
    c[last] = -c[last] * d[last - 1] * d[last - 1] / (x[last] - x[last - 3]);
  }
  for (std::size_t i = 1; i <= last; ++i) {
    const double t = d[i - 1] / b[i - 1];
    b[i] -= t * d[i - 1];
    c[i] -= t * c[i - 1];
  }
  c[last] /= b[last];
  for (std::size_t i = last; i-- > 0;) c[i] = (c[i] - d[i] * c[i + 1]) / b[i];
  b[last] = (y[last] - y[last - 1]) / d[last - 1] + d[last - 1] * (c[last - 1] + 2.0 * c[last]);
  for (std::size_t i = 0; i < last; ++i) {
    b[i] = (y[i + 1] - y[i]) / d[i] - d[i] * (c[i + 1] + 2.0 * c[i]);
    d[i] = (c[i + 1] - c[i]) / d[i];
    c[i] *= 3.0;
  }
  c[last] *= 3.0;
  d[last] = d[last - 1];
}

class ModelReader {
 public:
  ModelReader(const std::string& xml, std::string source) : source_(std::move(source)) {
    if (document_.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
      fail(std::string("not valid XML: ") + (document_.ErrorStr() ? document_.ErrorStr() : "unknown error"));
    }
  }

  OpenSimModel read() {
    const XMLElement* document = document_.FirstChildElement("OpenSimDocument");
    const XMLElement* model = document ? document->FirstChildElement("Model") : document_.FirstChildElement("Model");
    if (!model) fail("no <Model> element: this is not an OpenSim model file");
    model_.name = model->Attribute("name") ? model->Attribute("name") : "";
    const XMLElement* bodies = path(model, {"BodySet", "objects"});
    if (!bodies) fail("no <BodySet><objects>: the model has no bodies");
    for (const XMLElement* body = bodies->FirstChildElement("Body"); body; body = body->NextSiblingElement("Body")) {
      if (body->FirstChildElement("Joint")) {
        fail("body '" + name(body) + "' holds its joint: an OpenSim 3 model; open and save it in OpenSim 4 first");
      }
      model_.bodies.push_back(name(body));
    }
    const XMLElement* joints = path(model, {"JointSet", "objects"});
    if (!joints) fail("no <JointSet><objects>: the model has no joints");
    std::vector<OpenSimJoint> unordered;
    for (const XMLElement* joint = joints->FirstChildElement(); joint; joint = joint->NextSiblingElement()) {
      unordered.push_back(readJoint(*joint));
    }
    orderFromGround(std::move(unordered));
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw OpenSimModelError(source_ + ": " + what); }

  static std::string name(const XMLElement* element) {
    return element->Attribute("name") ? element->Attribute("name") : std::string();
  }

  static const XMLElement* path(const XMLElement* element, std::initializer_list<const char*> names) {
    for (const char* n : names) element = element ? element->FirstChildElement(n) : nullptr;
    return element;
  }

  Eigen::Vector3d vector3(const XMLElement* element, const std::string& what) const {
    const std::vector<double> v = numbers(element);
    if (v.size() != 3 || !std::isfinite(v[0]))
      fail(what + " must be three finite numbers, got '" + words(element) + "'");
    const Eigen::Vector3d vector(v[0], v[1], v[2]);
    if (vector.cwiseAbs().maxCoeff() > kMaxNumber) fail(what + " '" + words(element) + "' is beyond " + kMaxNumberText);
    return vector;
  }

  // A body from a socket path ("/bodyset/pelvis", "../pelvis", "/ground"); -1 for the ground.
  int bodyAt(const std::string& socket, const std::string& what) const {
    const std::string body = socket.substr(socket.find_last_of('/') + 1);
    if (body == "ground") return -1;
    const int index = model_.findBody(body);
    if (index < 0) fail(what + " names '" + socket + "', which is no body of the model");
    return index;
  }

  // A joint's socket: one of its own offset frames, or a body itself.
  void frame(const XMLElement& joint, const char* socket, int& body, Eigen::Isometry3d& offset) const {
    const std::string where = "joint '" + name(&joint) + "' " + socket;
    const std::string target = words(joint.FirstChildElement(socket));
    if (target.empty()) fail(where + " is missing");
    offset = Eigen::Isometry3d::Identity();
    for (const XMLElement* f = path(&joint, {"frames", "PhysicalOffsetFrame"}); f;
         f = f->NextSiblingElement("PhysicalOffsetFrame")) {
      if (name(f) != target) continue;
      body = bodyAt(words(f->FirstChildElement("socket_parent")), where + " frame '" + target + "' socket_parent");
      const Eigen::Vector3d angles = f->FirstChildElement("orientation")
                                         ? vector3(f->FirstChildElement("orientation"), where + " orientation")
                                         : Eigen::Vector3d::Zero();
      offset.translate(vector3(f->FirstChildElement("translation"), where + " frame '" + target + "' translation"));
      offset.rotate(Eigen::AngleAxisd(angles.x(), Eigen::Vector3d::UnitX()) *
                    Eigen::AngleAxisd(angles.y(), Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(angles.z(), Eigen::Vector3d::UnitZ()));
      return;
    }
    body = bodyAt(target, where);
  }

  int coordinate(const std::string& coordinate_name, bool rotational) {
    int index = model_.findCoordinate(coordinate_name);
    if (index < 0) {
      model_.coordinates.push_back({coordinate_name, rotational, 0.0});
      index = static_cast<int>(model_.coordinates.size()) - 1;
    }
    if (rotational) model_.coordinates[static_cast<std::size_t>(index)].rotational = true;
    return index;
  }

  // The joint's own <coordinates>: declared first so that defaults are known; motion type is
  // settled by the axes that use them.
  std::vector<int> declareCoordinates(const XMLElement& joint) {
    std::vector<int> declared;
    for (const XMLElement* c = path(&joint, {"coordinates", "Coordinate"}); c;
         c = c->NextSiblingElement("Coordinate")) {
      const int index = coordinate(name(c), false);
      model_.coordinates[static_cast<std::size_t>(index)].rotational = false;
      const std::vector<double> value = numbers(c->FirstChildElement("default_value"));
      if (value.size() == 1 && std::isfinite(value[0]))
        model_.coordinates[static_cast<std::size_t>(index)].default_value = value[0];
      declared.push_back(index);
    }
    return declared;
  }

  OpenSimFunction readFunction(const XMLElement* element, const std::string& where) const {
    OpenSimFunction f;
    if (!element) fail(where + " has no function");
    const std::string kind = element->Name();
    if (kind == "MultiplierFunction") {
      const std::vector<double> scale = numbers(element->FirstChildElement("scale"));
      if (scale.size() != 1 || !std::isfinite(scale[0])) fail(where + " MultiplierFunction needs one finite <scale>");
      const XMLElement* inner = element->FirstChildElement();
      while (inner && std::string(inner->Name()) == "scale") inner = inner->NextSiblingElement();
      if (inner && std::string(inner->Name()) == "function") inner = inner->FirstChildElement();
      f = readFunction(inner, where);
      f.scale *= scale[0];
      return f;
    }
    const auto count = [&](const char* child, std::size_t least) {
      std::vector<double> v = numbers(element->FirstChildElement(child));
      if (v.size() < least || !std::all_of(v.begin(), v.end(), [](double x) { return std::abs(x) <= kMaxNumber; })) {
        fail(where + " " + kind + " <" + child + "> needs at least " + std::to_string(least) +
             " finite numbers within " + kMaxNumberText + ", got '" + words(element->FirstChildElement(child)) + "'");
      }
      return v;
    };
    if (kind == "Constant") {
      f.kind = OpenSimFunction::Kind::kConstant;
      f.coefficients = count("value", 1);
    } else if (kind == "LinearFunction") {
      f.kind = OpenSimFunction::Kind::kLinear;
      f.coefficients = count("coefficients", 2);
    } else if (kind == "PolynomialFunction") {
      f.kind = OpenSimFunction::Kind::kPolynomial;
      f.coefficients = count("coefficients", 1);
    } else if (kind == "SimmSpline") {
      f.kind = OpenSimFunction::Kind::kSpline;
      f.x = count("x", 2);
      f.y = count("y", 2);
      if (f.x.size() != f.y.size())
        fail(where + " SimmSpline has " + std::to_string(f.x.size()) + " x and " + std::to_string(f.y.size()) + " y");
      for (std::size_t i = 1; i < f.x.size(); ++i) {
        if (!(f.x[i] > f.x[i - 1]))
          fail(where + " SimmSpline x must increase, it does not at knot " + std::to_string(i + 1));
      }
      fitSimmSpline(f);
      for (const std::vector<double>* c : {&f.b, &f.c, &f.d}) {
        if (!std::all_of(c->begin(), c->end(), [](double x) { return std::abs(x) <= 1e12; })) {
          fail(where + " SimmSpline knots are too close for a spline through them");
        }
      }
    } else {
      fail(where + " uses a " + kind +
           ", which is not read (LinearFunction, Constant, PolynomialFunction, SimmSpline, "
           "MultiplierFunction are)");
    }
    return f;
  }

  OpenSimTransformAxis readAxis(const XMLElement& element, bool rotation, const std::string& where) {
    OpenSimTransformAxis axis;
    const std::string names = words(element.FirstChildElement("coordinates"));
    if (names.find(' ') != std::string::npos)
      fail(where + " depends on several coordinates (" + names + "), which is not read");
    if (!names.empty()) axis.coordinate = coordinate(names, rotation);
    axis.axis = vector3(element.FirstChildElement("axis"), where + " axis");
    if (axis.axis.norm() < 1e-12) fail(where + " axis has no length");
    axis.axis.normalize();
    const XMLElement* function = element.FirstChildElement();
    while (function && (std::string(function->Name()) == "coordinates" || std::string(function->Name()) == "axis")) {
      function = function->NextSiblingElement();
    }
    if (function && std::string(function->Name()) == "function") function = function->FirstChildElement();
    axis.function = readFunction(function, where);
    return axis;
  }

  static OpenSimTransformAxis fixedAxis(const Eigen::Vector3d& direction, int coordinate_index) {
    OpenSimTransformAxis axis;
    axis.axis = direction;
    axis.coordinate = coordinate_index;
    axis.function.kind = coordinate_index < 0 ? OpenSimFunction::Kind::kConstant : OpenSimFunction::Kind::kLinear;
    axis.function.coefficients = coordinate_index < 0 ? std::vector<double>{0.0} : std::vector<double>{1.0, 0.0};
    return axis;
  }

  OpenSimJoint readJoint(const XMLElement& element) {
    OpenSimJoint joint;
    joint.name = name(&element);
    const std::string type = element.Name();
    const std::string where = "joint '" + joint.name + "' (" + type + ")";
    frame(element, "socket_parent_frame", joint.parent_body, joint.parent_offset);
    frame(element, "socket_child_frame", joint.child_body, joint.child_offset);
    if (joint.child_body < 0) fail(where + " moves the ground");
    const std::vector<int> declared = declareCoordinates(element);
    const auto declaredAt = [&](std::size_t i) { return i < declared.size() ? declared[i] : -1; };
    for (std::size_t k = 0; k < 3; ++k) {
      joint.rotations[k] = fixedAxis(Eigen::Vector3d::Unit(static_cast<int>(k)), -1);
      joint.translations[k] = fixedAxis(Eigen::Vector3d::Unit(static_cast<int>(k)), -1);
    }
    if (type == "CustomJoint") {
      const XMLElement* transform = element.FirstChildElement("SpatialTransform");
      if (!transform) fail(where + " has no <SpatialTransform>");
      for (const XMLElement* axis = transform->FirstChildElement("TransformAxis"); axis;
           axis = axis->NextSiblingElement("TransformAxis")) {
        const std::string axis_name = name(axis);
        const bool rotation = axis_name.rfind("rotation", 0) == 0;
        const bool translation = axis_name.rfind("translation", 0) == 0;
        const int k = axis_name.empty() ? 0 : axis_name.back() - '1';
        if ((!rotation && !translation) || k < 0 || k > 2)
          fail(where + " has a TransformAxis named '" + axis_name + "'");
        (rotation ? joint.rotations : joint.translations)[static_cast<std::size_t>(k)] =
            readAxis(*axis, rotation, where + " " + axis_name);
      }
    } else if (type == "PinJoint") {
      joint.rotations[0] = fixedAxis(Eigen::Vector3d::UnitZ(), declaredAt(0));
    } else if (type == "PlanarJoint") {
      joint.rotations[0] = fixedAxis(Eigen::Vector3d::UnitZ(), declaredAt(0));
      joint.translations[0] = fixedAxis(Eigen::Vector3d::UnitX(), declaredAt(1));
      joint.translations[1] = fixedAxis(Eigen::Vector3d::UnitY(), declaredAt(2));
    } else if (type != "WeldJoint") {
      fail(where + ": this joint type is not read (CustomJoint, PinJoint, PlanarJoint, WeldJoint are)");
    }
    if (declaredAt(0) >= 0 && (type == "PinJoint" || type == "PlanarJoint")) {
      model_.coordinates[static_cast<std::size_t>(declared[0])].rotational = true;
    }
    return joint;
  }

  void orderFromGround(std::vector<OpenSimJoint> unordered) {
    std::vector<int> placed_by(model_.bodies.size(), -1);
    for (std::size_t j = 0; j < unordered.size(); ++j) {
      int& by = placed_by[static_cast<std::size_t>(unordered[j].child_body)];
      if (by >= 0) {
        fail("body '" + model_.bodies[static_cast<std::size_t>(unordered[j].child_body)] +
             "' is the child of two joints ('" + unordered[static_cast<std::size_t>(by)].name + "', '" +
             unordered[j].name + "'): a closed loop is not read");
      }
      by = static_cast<int>(j);
    }
    std::vector<bool> placed(model_.bodies.size(), false);
    std::vector<bool> taken(unordered.size(), false);
    for (bool progress = true; progress;) {
      progress = false;
      for (std::size_t j = 0; j < unordered.size(); ++j) {
        const int parent = unordered[j].parent_body;
        if (taken[j] || (parent >= 0 && !placed[static_cast<std::size_t>(parent)])) continue;
        taken[j] = progress = true;
        placed[static_cast<std::size_t>(unordered[j].child_body)] = true;
        model_.joints.push_back(std::move(unordered[j]));
      }
    }
    for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
      if (!placed[b]) fail("body '" + model_.bodies[b] + "' is joined to the ground by no chain of joints");
    }
  }

  tinyxml2::XMLDocument document_;
  std::string source_;
  OpenSimModel model_;
};

}  // namespace

double OpenSimFunction::value(double argument) const {
  double y_value = 0.0;
  switch (kind) {
    case Kind::kConstant:
      y_value = coefficients[0];
      break;
    case Kind::kLinear:
      y_value = coefficients[0] * argument + coefficients[1];
      break;
    case Kind::kPolynomial:
      for (const double c_i : coefficients) y_value = y_value * argument + c_i;
      break;
    case Kind::kSpline: {
      if (argument <= x.front()) {
        y_value = y.front() + b.front() * (argument - x.front());
      } else if (argument >= x.back()) {
        y_value = y.back() + b.back() * (argument - x.back());
      } else {
        const std::size_t i = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), argument) - x.begin()) - 1;
        const double dx = argument - x[i];
        y_value = y[i] + dx * (b[i] + dx * (c[i] + dx * d[i]));
      }
      break;
    }
  }
  return scale * y_value;
}

int OpenSimModel::findBody(const std::string& body) const {
  const auto it = std::find(bodies.begin(), bodies.end(), body);
  return it == bodies.end() ? -1 : static_cast<int>(it - bodies.begin());
}

int OpenSimModel::findCoordinate(const std::string& coordinate) const {
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    if (coordinates[i].name == coordinate) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Isometry3d OpenSimModel::jointTransform(std::size_t joint, const std::vector<double>& coordinate_values) const {
  const OpenSimJoint& j = joints.at(joint);
  const auto value = [&](const OpenSimTransformAxis& axis) {
    return axis.function.value(axis.coordinate < 0 ? 0.0
                                                   : coordinate_values[static_cast<std::size_t>(axis.coordinate)]);
  };
  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  for (const OpenSimTransformAxis& axis : j.translations) moved.translation() += value(axis) * axis.axis;
  for (const OpenSimTransformAxis& axis : j.rotations) moved.rotate(Eigen::AngleAxisd(value(axis), axis.axis));
  return j.parent_offset * moved * j.child_offset.inverse();
}

std::vector<Eigen::Isometry3d> OpenSimModel::bodyTransforms(const std::vector<double>& coordinate_values) const {
  std::vector<Eigen::Isometry3d> world(bodies.size(), Eigen::Isometry3d::Identity());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const OpenSimJoint& joint = joints[j];
    const Eigen::Isometry3d local = jointTransform(j, coordinate_values);
    world[static_cast<std::size_t>(joint.child_body)] =
        joint.parent_body < 0 ? local : world[static_cast<std::size_t>(joint.parent_body)] * local;
  }
  return world;
}

std::vector<double> OpenSimModel::defaultCoordinates() const {
  std::vector<double> values;
  for (const OpenSimCoordinate& c : coordinates) values.push_back(c.default_value);
  return values;
}

OpenSimModel OpenSimModel::scaled(double factor) const {
  OpenSimModel model = *this;
  for (OpenSimJoint& joint : model.joints) {
    joint.parent_offset.translation() *= factor;
    joint.child_offset.translation() *= factor;
    for (OpenSimTransformAxis& axis : joint.translations) {
      if (axis.coordinate < 0 || coordinates[static_cast<std::size_t>(axis.coordinate)].rotational)
        axis.function.scale *= factor;
    }
  }
  return model;
}

OpenSimModel parseOpenSimModel(const std::string& xml, const std::string& source_name) {
  return ModelReader(xml, source_name).read();
}

OpenSimModel loadOpenSimModelFile(const std::string& path) {
  return parseOpenSimModel(readWholeFileOrThrow<OpenSimModelError>(path, "the OpenSim model file"), path);
}

}  // namespace dressed_human
