// Writes the relief figures' raw material (PNG images and CSV tables) into a directory:
// buckling wrinkles vs compression (seed 000 Figs. 6-8), Gaussian approximation error vs number of
// terms, skin parameter sweeps (paper 004 Figs. 11-18), a height/normal map with its mip chain.
// scripts/make_relief_figures.py runs this and assembles the panels into docs/relief/.
//
// Usage: relief_images <output_directory>
#include "dressed_human/core/relief/buckling_chain.h"
#include "dressed_human/core/relief/gaussian_fold_fit.h"
#include "dressed_human/core/relief/lambert_shading.h"
#include "dressed_human/core/io/png_writer.h"
#include "dressed_human/core/relief/skin_relief.h"
#include "dressed_human/core/relief/wrinkle_map.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <initializer_list>
#include <utility>
#include <string>

namespace {

using namespace dressed_human;

// Light from the upper left, as in the papers' figures.
const Eigen::Vector3d kLight(-0.45, -0.55, 1.0);

void writeShaded(const std::string& path, const ReliefMap& map) {
  writePng8(path, map.width, map.height, 1, shadeReliefMap(map, kLight));
}

std::string percent(double alpha) {
  std::ostringstream name;
  name << std::setw(3) << std::setfill('0') << static_cast<int>(std::lround(alpha * 100.0));
  return name.str();
}

void writeBucklingTables(const std::string& directory) {
  std::ofstream table(directory + "/buckling_solution.csv");
  table << "alpha,h1,w,h2,thickness,bend_angle_deg,eq10_residual_1,eq10_residual_2\n";
  const BucklingCell cell{1.0, 1.0};
  for (int step = 0; step <= 100; ++step) {
    const double alpha = step / 100.0;
    const BucklingSolution solution = solveBuckling(PatternKind::Y, alpha, cell);
    const Eigen::Vector2d residual = equation10Residual(solution.w, solution.h1, solution.h2, cell.half_width_x);
    table << alpha << ',' << solution.h1 << ',' << solution.w << ',' << solution.h2 << ',' << solution.h1 + solution.h2
          << ',' << solution.bend_angle * 180.0 / M_PI << ',' << residual[0] << ',' << residual[1] << '\n';
  }
}

void writeGaussianErrors(const std::string& directory) {
  std::ofstream table(directory + "/gaussian_error.csv");
  table << "pattern,alpha,terms,rms_error,max_height\n";
  const BucklingCell cell{1.0, 1.0};
  for (PatternKind kind : {PatternKind::I, PatternKind::Y, PatternKind::X}) {
    for (double alpha : {0.8, 0.6}) {
      const BucklingPattern pattern(kind, alpha, cell);
      for (int terms : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32}) {
        const GaussianFoldApproximation fit = fitGaussians(pattern, terms);
        table << patternName(kind) << ',' << alpha << ',' << terms << ',' << rmsApproximationError(pattern, fit) << ','
              << pattern.solution().h1 << '\n';
      }
    }
  }
}

// The tile the wrinkle figures and the smooth-fold table share: 4 cells around, 2 rows, 256^2.
WrinkleMapSpec foldTile(const char* chain, double alpha) {
  WrinkleMapSpec spec;
  spec.width_pixels = 256;
  spec.height_pixels = 256;
  spec.chain = chain;
  spec.cells_around = 4;
  spec.rows = 2;
  spec.alpha = {alpha};
  return spec;
}

// The smooth folds (the exact tile blurred, fourier_low_pass.h) against the exact ones, by
// harmonics kept per cell: height RMS error over h1 and the time to make a map (the cost).
void writeSmoothFoldErrors(const std::string& directory) {
  std::ofstream table(directory + "/smooth_fold_error.csv");
  // The default rides along so that the report states the default the display draws with.
  const int default_harmonics = WrinkleMapSpec{}.smooth_harmonics_per_cell;
  table << "pattern,alpha,harmonics_per_cell,rms_error,h1,ms_per_map,default_harmonics_per_cell\n";
  for (const auto& [chain, kind] : {std::make_pair("I", PatternKind::I), std::make_pair("YY", PatternKind::Y),
                                    std::make_pair("X", PatternKind::X)}) {
    for (const double alpha : {0.8, 0.6}) {
      WrinkleMapSpec spec = foldTile(chain, alpha);
      const ReliefMap exact = makeWrinkleMap(spec);
      spec.surface = WrinkleSurface::smoothFolds;
      for (int harmonics = 2; harmonics <= 24; harmonics += 2) {
        spec.smooth_harmonics_per_cell = harmonics;
        ReliefMap smooth;
        double ms = 1e300;  // the fastest of three: other processes only add time
        for (int round = 0; round < 3; ++round) {
          const auto start = std::chrono::steady_clock::now();
          smooth = makeWrinkleMap(spec);
          ms =
              std::min(ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        table << patternName(kind) << ',' << alpha << ',' << harmonics << ',' << rmsHeightDifference(smooth, exact)
              << ',' << solveBuckling(kind, alpha, spec.cell).h1 << ',' << ms << ',' << default_harmonics << '\n';
      }
    }
  }
}

void writeWrinkles(const std::string& directory) {
  for (const char* chain : {"X", "YY", "I"}) {
    for (double alpha : {1.0, 0.95, 0.9, 0.8, 0.7, 0.6}) {
      WrinkleMapSpec spec = foldTile(chain, alpha);
      spec.amplitude = 0.35;  // bump strength: the exact folds are 45 degrees steep at alpha 0.7
      writeShaded(directory + "/wrinkle_" + chain + "_alpha" + percent(alpha) + ".png", makeWrinkleMap(spec));
      spec.surface = WrinkleSurface::gaussianApproximation;
      spec.gaussian_terms = 8;
      writeShaded(directory + "/wrinkle_" + chain + "_gauss8_alpha" + percent(alpha) + ".png", makeWrinkleMap(spec));
      spec.surface = WrinkleSurface::smoothFolds;
      writeShaded(directory + "/wrinkle_" + chain + "_smooth_alpha" + percent(alpha) + ".png", makeWrinkleMap(spec));
    }
  }
  // One map, compression growing row by row (behind a bending knee).
  WrinkleMapSpec growth;
  growth.width_pixels = 512;
  growth.height_pixels = 768;
  growth.chain = "X";
  growth.cells_around = 6;
  growth.rows = 6;
  growth.alpha = {1.0, 0.97, 0.92, 0.85, 0.75, 0.6};
  growth.amplitude = 0.35;
  writeShaded(directory + "/wrinkle_growth_exact.png", makeWrinkleMap(growth));
  growth.surface = WrinkleSurface::gaussianApproximation;
  writeShaded(directory + "/wrinkle_growth_gauss8.png", makeWrinkleMap(growth));
  growth.surface = WrinkleSurface::smoothFolds;
  writeShaded(directory + "/wrinkle_growth_smooth.png", makeWrinkleMap(growth));
}

SkinReliefParameters baseSkin() {
  SkinReliefParameters parameters;
  parameters.cell_size = 1.0 / 8.0;
  parameters.levels = 1;
  parameters.seed = 7;
  return parameters;
}

void writeSkin(const std::string& directory, const std::string& name, const SkinReliefParameters& parameters,
               int size = 320) {
  writeShaded(directory + "/skin_" + name + ".png", SkinRelief(parameters).render(size, size));
}

// One figure per value of one parameter, the others as baseSkin(): skin_<name>_<label>.png.
template <typename Member, typename Label>
void writeSkinSweep(const std::string& directory, const std::string& name, Member SkinReliefParameters::*member,
                    std::initializer_list<Member> values, Label label) {
  for (const Member value : values) {
    SkinReliefParameters parameters = baseSkin();
    parameters.*member = value;
    writeSkin(directory, name + "_" + label(value), parameters);
  }
}

void writeSkinSweeps(const std::string& directory) {
  for (double slope : {0.8, 3.0, 12.0}) {
    SkinReliefParameters parameters = baseSkin();
    parameters.profile = BezierProfile::fromEdgeSlope(slope);
    std::ostringstream name;
    name << "slope_" << slope;
    writeSkin(directory, name.str(), parameters);
  }
  {  // Two Bezier pieces are out of scope; a profile with a sharp crest stands in for Fig. 11c.
    SkinReliefParameters parameters = baseSkin();
    parameters.profile.first_inner = {0.6, 0.05};
    parameters.profile.second_inner = {0.9, 0.4};
    writeSkin(directory, "slope_late", parameters);
  }
  writeSkinSweep(directory, "roundness", &SkinReliefParameters::roundness, {0.0, 0.4, 1.0}, percent);
  writeSkinSweep(directory, "jitter", &SkinReliefParameters::jitter, {0.0, 0.2, 0.45}, percent);
  writeSkinSweep(directory, "wobble", &SkinReliefParameters::wobble, {0.0, 0.12, 0.25}, percent);
  writeSkinSweep(directory, "levels", &SkinReliefParameters::levels, {1, 2, 3},
                 [](int n) { return std::to_string(n); });
  const double stretch = 2.5;
  for (const auto& [name, angle] :
       {std::pair<const char*, double>{"none", -1.0}, {"horizontal", 0.0}, {"vertical", M_PI / 2}}) {
    SkinReliefParameters parameters = baseSkin();
    if (angle >= 0.0) {
      parameters.direction_angle = angle;
      parameters.direction_stretch = stretch;
    }
    writeSkin(directory, std::string("direction_") + name, parameters);
  }
  // Fig. 18: all together, three levels.
  SkinReliefParameters skin = baseSkin();
  skin.cell_size = 1.0 / 10.0;
  skin.levels = 3;
  skin.roundness = 0.3;
  skin.wobble = 0.15;
  skin.profile = BezierProfile::fromEdgeSlope(4.0);
  writeSkin(directory, "fig18_a", skin, 480);
  SkinReliefParameters vertical = skin;
  vertical.direction_angle = M_PI / 2;
  vertical.direction_stretch = 2.0;
  writeSkin(directory, "fig18_b", vertical, 480);
  SkinReliefParameters horizontal = skin;
  horizontal.direction_stretch = 2.0;
  writeSkin(directory, "fig18_c", horizontal, 480);
  SkinReliefParameters first_level_only = horizontal;
  first_level_only.direction_stretch = 3.0;
  first_level_only.directional_levels = 1;
  writeSkin(directory, "fig18_f", first_level_only, 480);

  // Maps for the renderer: height (16-bit), tangent-space normals, mip chain, shaded tile.
  const ReliefMap map = SkinRelief(skin).render(512, 512);
  writePng16Grey(directory + "/skin_height.png", map.width, map.height, encodeHeightMap16(map));
  const std::vector<ReliefMap> mips = buildMipChain(map, 6);
  for (std::size_t level = 0; level < mips.size(); ++level) {
    writePng8(directory + "/skin_normal_mip" + std::to_string(level) + ".png", mips[level].width, mips[level].height, 3,
              encodeNormalMapRgb(mips[level]));
    writeShaded(directory + "/skin_shaded_mip" + std::to_string(level) + ".png", mips[level]);
  }
  std::ofstream info(directory + "/skin_height_range.txt");
  info << "skin_height.png maps 0..65535 to heights " << map.minimumHeight() << " .. " << map.maximumHeight()
       << " (tile units)\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: relief_images <output_directory>\n";
    return 2;
  }
  const std::string directory = argv[1];
  try {
    writeBucklingTables(directory);
    writeGaussianErrors(directory);
    writeSmoothFoldErrors(directory);
    writeWrinkles(directory);
    writeSkinSweeps(directory);
  } catch (const std::exception& error) {
    std::cerr << "relief_images: " << error.what() << '\n';
    return 1;
  }
  std::cout << "wrote relief images to " << directory << '\n';
  return 0;
}
