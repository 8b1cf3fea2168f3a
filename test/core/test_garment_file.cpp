// Garment files (garment_file.h): the defaults load; bad files fail with file:line:col and the
// key path.
#include <gtest/gtest.h>

#include "garment_test_support.h"

namespace dressed_human {
namespace {

using namespace garment_test;

const std::string kSkirt = R"(name: skirt
type: skirt
colour: [0.7, 0.2, 0.3]
ease: 0.015
rows:
  - {frame: waist, centre: [0.0, 0.0, 0.07], radius: [0.10, 0.14]}
  - {frame: body, centre: [0.0, 0.0, 0.0], radius: [0.115, 0.165]}
  - {frame: body, centre: [0.0, 0.0, -0.07], radius: [0.125, 0.18]}
legs:
  length: 0.3
  top: {frame: l_hip, centre: [0.0, -0.09, 0.02], radius: [0.125, 0.19]}
  knee: {frame: l_hip, centre: [0.0, -0.09, 0.42], radius: [0.15, 0.23]}
  long: {frame: l_knee, centre: [0.0, -0.09, 0.38], radius: [0.19, 0.28]}
)";

std::string errorOf(const std::string& text) {
  try {
    parseGarmentYaml(text, skeleton(), "bad.yaml");
  } catch (const GarmentError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kSkirt;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(GarmentFile, DefaultGarmentsLoadAndBuild) {
  for (const std::string name : {"jacket", "skirt", "pants", "one_piece"}) {
    const GarmentDescription d = garmentFile(name);
    EXPECT_EQ(d.rows.size(), garmentRowCount(d.type)) << name;
    EXPECT_NO_THROW(Garment(d, skeleton(), body().shape)) << name;
  }
  const GarmentDescription skirt = parseGarmentYaml(kSkirt, skeleton());
  EXPECT_EQ(skirt.type, GarmentType::kSkirt);
  EXPECT_DOUBLE_EQ(skirt.legs.length, 0.3);
  EXPECT_DOUBLE_EQ(skirt.ease, 0.015);
}

TEST(GarmentFile, ErrorsNameFileLineColumnAndKey) {
  EXPECT_EQ(errorOf(replaced("radius: [0.115, 0.165]", "radius: [0.115, -0.1]")),
            "bad.yaml:7:60: rows[1].radius[1]: must be > 0, got -0.1");
  EXPECT_EQ(errorOf(replaced("radius: [0.115, 0.165]", "radius: [0.115, 1e300]")),
            "bad.yaml:7:60: rows[1].radius[1]: 1e+300 m is outside [0, 1] m");
  EXPECT_NE(errorOf(replaced("ease: 0.015", "ease: 1e9")).find("ease: 1e+09 m is outside [0, 0.5] m"),
            std::string::npos)
      << errorOf(replaced("ease: 0.015", "ease: 1e9"));
  EXPECT_EQ(errorOf(replaced("type: skirt", "type: kilt")),
            "bad.yaml:2:7: type: unknown garment type 'kilt'; expected jacket, skirt, pants or one_piece");
  EXPECT_EQ(errorOf(replaced("length: 0.3", "length: 1.5")),
            "bad.yaml:10:11: legs.length: must lie in [0, 1] (or be \"knee\"), got 1.5");
  EXPECT_EQ(errorOf(replaced("frame: body, centre: [0.0, 0.0, 0.0]", "frame: spine, centre: [0.0, 0.0, 0.0]")),
            "bad.yaml:7:13: rows[1].frame: unknown frame 'spine'; expected \"body\" or a bone of the skeleton");
  EXPECT_EQ(errorOf(replaced("ease: 0.015", "ease: .nan")), "bad.yaml:4:7: ease: expected a finite number, got '.nan'");
  EXPECT_EQ(errorOf(replaced("long: {frame: l_knee", "long: {frame: l_elbow")),
            "bad.yaml:13:17: legs.long.frame: must be a child bone of 'l_hip' (Eq. 8: frame j below frame i)");
  EXPECT_EQ(errorOf(replaced("top: {frame: l_hip", "top: {frame: waist")),
            "bad.yaml:11:16: legs.top.frame: expected a left bone (l_...), mirrored to the right, got 'waist'");
  EXPECT_EQ(errorOf(replaced("colour: [0.7, 0.2, 0.3]", "colour: [0.7, 2.0, 0.3]")),
            "bad.yaml:3:15: colour[1]: must lie in [0, 1], got 2.0");
  EXPECT_EQ(errorOf(replaced("ease: 0.015", "ease: 0.015\nsize: 3")),
            "bad.yaml:5:1: size: unknown key; expected one of: colour, crotch, ease, legs, name, rows, sleeve, type");
  EXPECT_NE(errorOf(replaced("  - {frame: body, centre: [0.0, 0.0, -0.07], radius: [0.125, 0.18]}\n", ""))
                .find("rows: expected 3 rings, got 2"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced("legs:", "crotch: {frame: body, point: [0, 0, 0]}\nlegs:"))
                .find("crotch: only pants have a crotch"),
            std::string::npos);
  EXPECT_NE(errorOf("rows: [").find("bad.yaml:1:"), std::string::npos);
  // Pants: the crotch's twist ellipses (garment.h).
  {
    std::string pants = replaced("type: skirt", "type: pants");
    pants += "crotch: {frame: body, point: [0, 0, -0.2], radius: [0.17, 0.01], leg_radius: [0.3, -0.01]}\n";
    EXPECT_NE(errorOf(pants).find("crotch.leg_radius[1]: must be > 0, got -0.01"), std::string::npos) << errorOf(pants);
    const GarmentDescription ok = parseGarmentYaml(
        replaced("type: skirt", "type: pants") + "crotch: {frame: body, point: [0, 0, -0.2], radius: [0.17, 0.02]}\n",
        skeleton());
    EXPECT_EQ(ok.crotch_radius, Eigen::Vector2d(0.17, 0.02));
    EXPECT_EQ(ok.crotch_leg_radius, ok.crotch_radius);  // defaults to radius
    // Pants legs have two patch rows (garment.h): 4 inner control rows, not the skirt's 2.
    const std::string crotch = "crotch: {frame: body, point: [0, 0, -0.2]}\n";
    std::string two = replaced("length: 0.3", "length: 0.3\n  rows: [0.3, 0.6]");
    two.replace(two.find("type: skirt"), 11, "type: pants");
    EXPECT_NE(errorOf(two + crotch).find("legs.rows: expected a list of 4 fractions for a pants"), std::string::npos)
        << errorOf(two + crotch);
    std::string four = replaced("length: 0.3", "length: 0.3\n  rows: [0.2, 0.5, 0.4, 0.8]");
    four.replace(four.find("type: skirt"), 11, "type: pants");
    EXPECT_NE(errorOf(four + crotch).find("legs.rows[2]: fractions must increase strictly within (0, 1), got 0.4"),
              std::string::npos)
        << errorOf(four + crotch);
    EXPECT_EQ(parseGarmentYaml(four.replace(four.find("0.4,"), 4, "0.6,") + crotch, skeleton()).legs.row_fractions,
              (std::vector<double>{0.2, 0.5, 0.6, 0.8}));
  }
  EXPECT_NE(errorOf(replaced("length: 0.3", "length: 0.3\n  rows: [0.3, 0.6, 0.8]"))
                .find("legs.rows: expected a list of 2 fractions for a skirt"),
            std::string::npos);
  EXPECT_EQ(errorOf(""), "bad.yaml: the garment file is empty");
  EXPECT_THROW(loadGarmentFile("/nonexistent/skirt.yaml", skeleton()), GarmentError);
}

}  // namespace
}  // namespace dressed_human
