#include "dressed_human/core/locomotion/normative_gait.h"

#include <algorithm>
#include <cmath>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/io/yaml_reader.h"

namespace dressed_human {
namespace {

using Reader = YamlReader<LocomotionError>;

FourierSeries readCurve(const Reader& reader, const YAML::Node& node, const std::string& key) {
  reader.requireMap(node, key);
  reader.rejectUnknownKeys(node, key, {"a0", "a", "b", "rms_residual_deg"});
  FourierSeries s;
  s.a0 = reader.numberWithin(reader.require(node, "a0", key), key + ".a0", -2.0 * M_PI, 2.0 * M_PI, " rad");
  s.a = reader.numbers(reader.require(node, "a", key), key + ".a", 0, "", 1);
  s.b = reader.numbers(reader.require(node, "b", key), key + ".b", s.a.size(), "(as many as in a)", 1);
  if (s.a.size() > MotionLimits::kMaxOrder)
    reader.fail(node, key, "more harmonics than " + std::to_string(MotionLimits::kMaxOrder));
  double reach = 0.5 * std::abs(s.a0);
  for (std::size_t n = 0; n < s.a.size(); ++n) reach += std::hypot(s.a[n], s.b[n]);
  if (reach > MotionLimits::kMaxAngle)
    reader.fail(node, key, "reaches beyond a full turn: not a joint angle in radians");
  return s;
}

}  // namespace

NormativeGait parseNormativeGaitYaml(const std::string& yaml_text, const std::string& source_name) {
  const Reader reader(source_name);
  const YAML::Node document = reader.load(yaml_text, "the gait table");
  reader.rejectUnknownKeys(document, "", {"classes"});
  const YAML::Node classes = reader.require(document, "classes", "");
  if (!classes.IsSequence() || classes.size() == 0) reader.fail(classes, "classes", "expected a list of speed classes");
  NormativeGait gait;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const std::string key = "classes[" + std::to_string(i) + "]";
    const YAML::Node entry = classes[i];
    reader.requireMap(entry, key);
    reader.rejectUnknownKeys(
        entry, key,
        {"name", "dimensionless_speed", "dimensionless_cadence", "dimensionless_cadence_sd", "dimensionless_stride",
         "dimensionless_stride_sd", "speed_range", "foot_off_percent", "curves"});
    NormativeGaitClass c;
    c.name = reader.text(reader.require(entry, "name", key), key + ".name");
    // Dimensionless walking: 0.05 is a shuffle, 1.0 the walk-run transition (Froude number 1).
    c.speed = reader.numberWithin(reader.require(entry, "dimensionless_speed", key), key + ".dimensionless_speed", 0.05,
                                  1.0, "");
    c.cadence = reader.numberWithin(reader.require(entry, "dimensionless_cadence", key), key + ".dimensionless_cadence",
                                    0.05, 2.0, "");
    c.stride = reader.numberWithin(reader.require(entry, "dimensionless_stride", key), key + ".dimensionless_stride",
                                   0.1, 4.0, "");
    // Optional: how much the class's subjects differ (0: not given).
    if (entry["dimensionless_cadence_sd"]) {
      c.cadence_sd =
          reader.numberWithin(entry["dimensionless_cadence_sd"], key + ".dimensionless_cadence_sd", 0.0, 1.0, "");
    }
    if (entry["dimensionless_stride_sd"]) {
      c.stride_sd =
          reader.numberWithin(entry["dimensionless_stride_sd"], key + ".dimensionless_stride_sd", 0.0, 2.0, "");
    }
    if (!gait.classes.empty() && c.speed <= gait.classes.back().speed) {
      reader.fail(entry, key + ".dimensionless_speed", "the classes must be listed by increasing speed");
    }
    const YAML::Node curves = reader.require(entry, "curves", key);
    reader.requireMap(curves, key + ".curves");
    for (const char* name : kSagittalCurves) {
      c.curves[name] = readCurve(reader, reader.require(curves, name, key + ".curves"), key + ".curves." + name);
    }
    c.curves[kPelvisTiltCurve] = readCurve(reader, reader.require(curves, kPelvisTiltCurve, key + ".curves"),
                                           key + ".curves." + kPelvisTiltCurve);
    gait.classes.push_back(std::move(c));
  }
  return gait;
}

NormativeGait loadNormativeGaitFile(const std::string& path) {
  return parseNormativeGaitYaml(readWholeFileOrThrow<LocomotionError>(path, "gait table"), path);
}

FourierSeries NormativeGait::curveAt(const std::string& curve, double speed) const {
  const auto& c = classes;
  if (speed <= c.front().speed) return c.front().curves.at(curve);
  if (speed >= c.back().speed) return c.back().curves.at(curve);
  std::size_t k = 1;
  while (c[k].speed < speed) ++k;
  const double t = (speed - c[k - 1].speed) / (c[k].speed - c[k - 1].speed);
  return mixOf(inCycles(c[k - 1].curves.at(curve)), inCycles(c[k].curves.at(curve)), t);
}

FourierSeries inCycles(const FourierSeries& series) {
  // A phase p: cos(n(t + p)) = cos(np) cos(nt) - sin(np) sin(nt), sin(n(t + p)) = sin(np) cos(nt) + cos(np) sin(nt).
  FourierSeries s = series;
  s.period = 1.0;
  s.phase = 0.0;
  for (std::size_t n = 0; n < s.a.size(); ++n) {
    const double c = std::cos(static_cast<double>(n + 1) * series.phase);
    const double sn = std::sin(static_cast<double>(n + 1) * series.phase);
    s.a[n] = series.a[n] * c + series.b[n] * sn;
    s.b[n] = series.b[n] * c - series.a[n] * sn;
  }
  return s;
}

FourierSeries sumOf(const FourierSeries& a, const FourierSeries& b, double b_weight) {
  FourierSeries s = a;
  s.a0 += b_weight * b.a0;
  s.a.resize(std::max(a.a.size(), b.a.size()), 0.0);
  s.b.resize(s.a.size(), 0.0);
  for (std::size_t n = 0; n < b.a.size(); ++n) {
    s.a[n] += b_weight * b.a[n];
    s.b[n] += b_weight * b.b[n];
  }
  return s;
}

FourierSeries mixOf(const FourierSeries& a, const FourierSeries& b, double t) {
  FourierSeries scaled = a;
  scaled.a0 *= 1.0 - t;
  for (double& value : scaled.a) value *= 1.0 - t;
  for (double& value : scaled.b) value *= 1.0 - t;
  return sumOf(scaled, b, t);
}

}  // namespace dressed_human
