#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/io/text_file.h"

#include <cmath>
#include <set>

#include "dressed_human/core/io/yaml_reader.h"

namespace dressed_human {

const char* garmentTypeName(GarmentType type) {
  switch (type) {
    case GarmentType::kJacket:
      return "jacket";
    case GarmentType::kSkirt:
      return "skirt";
    case GarmentType::kPants:
      return "pants";
    case GarmentType::kOnePiece:
      return "one_piece";
  }
  return "?";
}

std::size_t garmentRowCount(GarmentType type) {
  switch (type) {
    case GarmentType::kJacket:
      return 6;
    case GarmentType::kSkirt:
      return 3;
    case GarmentType::kPants:
      return 3;
    case GarmentType::kOnePiece:
      return 7;
  }
  return 0;
}

std::size_t legRowFractionCount(GarmentType type) {
  switch (type) {
    case GarmentType::kJacket:
      return 0;
    case GarmentType::kSkirt:
      return 2;
    case GarmentType::kPants:
      return 4;
    case GarmentType::kOnePiece:
      return 2;
  }
  return 0;
}

namespace {

// The project's strict reader (file:line:col, key path) plus what garments need: fixed-size
// vectors, frame names checked against the skeleton, rings.
// Ring offsets and radii in metres: a garment around a person, not a tent (metres expected).
constexpr double kMaxOffset = 2.0;
constexpr double kMaxRadius = 1.0;
constexpr double kMaxEase = 0.5;

class GarmentYamlReader : public YamlReader<GarmentError> {
 public:
  GarmentYamlReader(std::string source, const Skeleton& skeleton)
      : YamlReader<GarmentError>(std::move(source)), skeleton_(skeleton) {}

  template <int N>
  Eigen::Matrix<double, N, 1> vector(const YAML::Node& node, const std::string& key) const {
    if (!node.IsSequence() || node.size() != N) {
      fail(node, key, "expected a list of " + std::to_string(N) + " numbers, got " + describe(node));
    }
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = number(node[i], key + "[" + std::to_string(i) + "]");
    return v;
  }

  // A frame name: "body" or a bone. `need`: "" any, "left" an l_ bone with an r_ mirror.
  std::string frame(const YAML::Node& node, const std::string& key, bool left_only) const {
    const std::string name = text(node, key);
    if (name == "body" && !left_only) return name;
    if (skeleton_.findBone(name) < 0)
      fail(node, key, "unknown frame '" + name + "'; expected \"body\" or a bone of the skeleton");
    if (left_only && name.rfind("l_", 0) != 0)
      fail(node, key, "expected a left bone (l_...), mirrored to the right, got '" + name + "'");
    if (name.rfind("l_", 0) == 0 && skeleton_.findBone("r_" + name.substr(2)) < 0) {
      fail(node, key, "left bone '" + name + "' has no mirror 'r_" + name.substr(2) + "'");
    }
    return name;
  }

  GarmentRing ring(const YAML::Node& node, const std::string& key, bool left_only) const {
    requireMap(node, key);
    rejectUnknownKeys(node, key, {"frame", "centre", "radius"});
    GarmentRing r;
    r.frame = frame(require(node, "frame", key), key + ".frame", left_only);
    r.centre = vector<3>(require(node, "centre", key), key + ".centre");
    const YAML::Node centre = require(node, "centre", key);
    for (int i = 0; i < 3; ++i) {  // in its bone's frame: within a body's reach of the bone
      numberWithin(centre[i], key + ".centre[" + std::to_string(i) + "]", -kMaxOffset, kMaxOffset, " m");
    }
    const YAML::Node radius = require(node, "radius", key);
    r.radius = vector<2>(radius, key + ".radius");
    for (int i = 0; i < 2; ++i) {
      if (r.radius[i] <= 0.0) {
        fail(radius[i], key + ".radius[" + std::to_string(i) + "]", "must be > 0, got " + radius[i].Scalar());
      }
      numberWithin(radius[i], key + ".radius[" + std::to_string(i) + "]", 0.0, kMaxRadius, " m");
    }
    return r;
  }

  std::vector<GarmentRing> rings(const YAML::Node& node, const std::string& key, std::size_t count,
                                 bool left_only) const {
    if (!node.IsSequence()) fail(node, key, "expected a list of rings, got " + describe(node));
    if (node.size() != count) {
      fail(node, key, "expected " + std::to_string(count) + " rings, got " + std::to_string(node.size()));
    }
    std::vector<GarmentRing> out;
    for (std::size_t i = 0; i < node.size(); ++i)
      out.push_back(ring(node[i], key + "[" + std::to_string(i) + "]", left_only));
    return out;
  }

  const Skeleton& skeleton() const { return skeleton_; }

 private:
  const Skeleton& skeleton_;
};

// The pants' crotch: its midline frame, point and the radii of its twist ring (garment.h).
void readCrotch(const GarmentYamlReader& reader, const YAML::Node& crotch, GarmentDescription& g) {
  reader.requireMap(crotch, "crotch");
  reader.rejectUnknownKeys(crotch, "crotch", {"frame", "point", "radius", "leg_radius"});
  g.crotch_frame = reader.frame(reader.require(crotch, "frame", "crotch"), "crotch.frame", false);
  if (g.crotch_frame.rfind("l_", 0) == 0 || g.crotch_frame.rfind("r_", 0) == 0) {
    reader.fail(crotch["frame"], "crotch.frame", "must be a frame on the body's midline (body, waist, ...)");
  }
  g.crotch = reader.vector<3>(reader.require(crotch, "point", "crotch"), "crotch.point");
  for (int i = 0; i < 3; ++i) {
    reader.numberWithin(crotch["point"][i], "crotch.point[" + std::to_string(i) + "]", -kMaxOffset, kMaxOffset, " m");
  }
  auto radius = [&](const char* key, Eigen::Vector2d& out) {
    if (!crotch[key]) return;
    const std::string path = std::string("crotch.") + key;
    out = reader.vector<2>(crotch[key], path);
    for (int i = 0; i < 2; ++i) {
      if (!(out[i] > 0.0))
        reader.fail(crotch[key][i], path + "[" + std::to_string(i) + "]",
                    "must be > 0, got " + crotch[key][i].Scalar());
      reader.numberWithin(crotch[key][i], path + "[" + std::to_string(i) + "]", 0.0, kMaxRadius, " m");
    }
  };
  radius("radius", g.crotch_radius);
  g.crotch_leg_radius = g.crotch_radius;
  radius("leg_radius", g.crotch_leg_radius);
}

}  // namespace

GarmentDescription parseGarmentYaml(const std::string& yaml_text, const Skeleton& skeleton,
                                    const std::string& source_name) {
  const GarmentYamlReader reader(source_name, skeleton);
  const YAML::Node document = reader.load(yaml_text, "the garment file");
  reader.rejectUnknownKeys(document, "", {"name", "type", "colour", "ease", "rows", "sleeve", "legs", "crotch"});

  GarmentDescription g;
  if (document["name"]) g.name = reader.text(document["name"], "name");
  const YAML::Node type = reader.require(document, "type", "");
  const std::string type_name = reader.text(type, "type");
  if (type_name == "jacket")
    g.type = GarmentType::kJacket;
  else if (type_name == "skirt")
    g.type = GarmentType::kSkirt;
  else if (type_name == "pants")
    g.type = GarmentType::kPants;
  else if (type_name == "one_piece")
    g.type = GarmentType::kOnePiece;
  else
    reader.fail(type, "type", "unknown garment type '" + type_name + "'; expected jacket, skirt, pants or one_piece");
  if (g.name.empty()) g.name = type_name;

  if (document["colour"]) {
    g.colour = reader.vector<3>(document["colour"], "colour");
    for (int i = 0; i < 3; ++i) {
      if (g.colour[i] < 0.0 || g.colour[i] > 1.0) {
        reader.fail(document["colour"][i], "colour[" + std::to_string(i) + "]",
                    "must lie in [0, 1], got " + document["colour"][i].Scalar());
      }
    }
  }
  if (document["ease"]) {
    g.ease = reader.number(document["ease"], "ease");
    if (g.ease < 0.0) reader.fail(document["ease"], "ease", "must be >= 0 metres, got " + document["ease"].Scalar());
    reader.numberWithin(document["ease"], "ease", 0.0, kMaxEase, " m");
  }
  g.rows = reader.rings(reader.require(document, "rows", ""), "rows", garmentRowCount(g.type), false);

  const bool has_legs = g.type != GarmentType::kJacket;
  if (document["sleeve"]) {
    if (g.type == GarmentType::kSkirt || g.type == GarmentType::kPants) {
      reader.fail(document["sleeve"], "sleeve", std::string("a ") + type_name + " has no sleeves");
    }
    g.sleeve = reader.rings(document["sleeve"], "sleeve", 4, true);
  } else if (g.type == GarmentType::kJacket) {
    reader.require(document, "sleeve", "");
  }
  if (has_legs) {
    const YAML::Node legs = reader.require(document, "legs", "");
    reader.requireMap(legs, "legs");
    reader.rejectUnknownKeys(legs, "legs", {"length", "rows", "top", "knee", "long"});
    if (const YAML::Node rows = legs["rows"]) {
      const std::size_t count = legRowFractionCount(g.type);
      if (!rows.IsSequence() || rows.size() != count) {
        reader.fail(rows, "legs.rows",
                    "expected a list of " + std::to_string(count) + " fractions for a " + type_name + ", got " +
                        reader.describe(rows));
      }
      double previous = 0.0;
      for (std::size_t i = 0; i < count; ++i) {
        const std::string key = "legs.rows[" + std::to_string(i) + "]";
        const double f = reader.number(rows[i], key);
        if (!(f > previous && f < 1.0))
          reader.fail(rows[i], key, "fractions must increase strictly within (0, 1), got " + rows[i].Scalar());
        g.legs.row_fractions.push_back(f);
        previous = f;
      }
    }
    const YAML::Node length = reader.require(legs, "length", "legs");
    if (length.IsScalar() && length.Scalar() == "knee") {
      g.legs.at_knee = true;
    } else {
      g.legs.length = reader.number(length, "legs.length");
      if (g.legs.length < 0.0 || g.legs.length > 1.0) {
        reader.fail(length, "legs.length", "must lie in [0, 1] (or be \"knee\"), got " + length.Scalar());
      }
    }
    g.legs.top = reader.ring(reader.require(legs, "top", "legs"), "legs.top", true);
    g.legs.knee = reader.ring(reader.require(legs, "knee", "legs"), "legs.knee", true);
    const YAML::Node long_node = reader.require(legs, "long", "legs");
    g.legs.long_hem = reader.ring(long_node, "legs.long", true);
    if (g.legs.top.frame != g.legs.knee.frame) {
      reader.fail(legs["top"], "legs.top.frame",
                  "must be the knee ring's frame '" + g.legs.knee.frame + "' (both are thigh-frame rings)");
    }
    const int upper = skeleton.findBone(g.legs.knee.frame);
    const int lower = skeleton.findBone(g.legs.long_hem.frame);
    if (skeleton.bone(static_cast<std::size_t>(lower)).parent != upper) {
      reader.fail(long_node["frame"], "legs.long.frame",
                  "must be a child bone of '" + g.legs.knee.frame + "' (Eq. 8: frame j below frame i)");
    }
  } else if (document["legs"]) {
    reader.fail(document["legs"], "legs", "a jacket has no legs part");
  }
  if (g.type == GarmentType::kPants) {
    readCrotch(reader, reader.require(document, "crotch", ""), g);
  } else if (document["crotch"]) {
    reader.fail(document["crotch"], "crotch", "only pants have a crotch");
  }
  for (std::size_t i = 0; i < g.rows.size(); ++i) {
    if (g.rows[i].frame.rfind("r_", 0) == 0) {
      reader.fail(document["rows"][i]["frame"], "rows[" + std::to_string(i) + "].frame",
                  "use the left bone; the right half is mirrored");
    }
  }
  return g;
}

GarmentDescription loadGarmentFile(const std::string& path, const Skeleton& skeleton) {
  const std::string text = readWholeFileOrThrow<GarmentError>(path, "the garment file");
  const std::size_t slash = path.find_last_of('/');
  return parseGarmentYaml(text, skeleton, slash == std::string::npos ? path : path.substr(slash + 1));
}

}  // namespace dressed_human
