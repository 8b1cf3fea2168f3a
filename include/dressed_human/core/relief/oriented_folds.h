// Oriented folds (issue 21; SPEC §4's placement, which the seed leaves to the renderer): the
// garments' relief drawn from two periodic fold tiles -- I folds for slight compression, the
// Y-Y chain for strong -- turned so that the folds run across the compression at every vertex.
//
// Orientation. A tile turned by an arbitrary, varying angle swirls (a turn by dtheta moves a
// point r tiles from the turn's centre by r dtheta) and breaks at every patch edge. So the tile
// is drawn at twelve fixed orientations, each a similarity y = A x of the patch's (u, v) with
// an integer matrix A = k [[q, -p], [p, q]]: its folds run along (p, q), and it maps the patch
// lattice into the tile's, so every orientation meets itself across patch edges. Scale k |(p, q)|
// is the number of tiles per patch across the folds; (1, 0) and (0, 1) at k = 3, the diagonals
// at k = 2, and (3, 1), (3, 2), (2, 3), (1, 3) and their mirrors at k = 1 keep it within 2.8-3.6
// (6-7 cells per patch, 4-5 cm on the default garments), with orientations at most 18.4 degrees
// apart. Heights shrink with the scale (similar folds), so slopes keep their size.
//
// Blending. The vertex's fold axis (VertexStretch::fold_axis, a double angle) gives the folds'
// angle; the two orientations either side of it are blended by a smoothstep of where it lies
// between them: at most two at a time, continuous in the axis, so neither the surface nor time
// shows a jump. Where no direction is preferred a small bias turns the axis towards the tile as
// laid out (folds along v: around the limb).
//
// Pattern. Strength below 0.4 (alpha above ~0.9 at the default threshold and saturation) draws
// the I tile, above 0.8 the Y-Y tile, blended in between: I where compression is slight, the
// chain that curls around sleeves and legs where it is strong.
//
// What the display draws since issue 40 is foldCoordinateRelief: the same tiles laid along the
// fold direction field by fold coordinates (fold_coordinates.h), since where the folds' angle
// turns this blend mixes two patterns of unrelated phase, which read as creases. orientedFolds
// stays for displaced geometry without coordinates and as the reference the coordinates are
// checked against (at an orientation's own angle both draw the same). relief_surface.frag
// (FOLD_COORDINATES) transcribes foldCoordinateRelief(); the tests hold this one.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/relief_sample.h"

namespace dressed_human {

constexpr int kFoldOrientations = 12;
/// Tiles per patch across the folds as laid out (orientations 0 and 6).
constexpr int kFoldTilesPerPatch = 3;
/// Added to the fold axis before its angle is taken: the tile as laid out where no direction is
/// preferred.
constexpr float kFoldAxisBias = 0.02f;

/// Orientation k: its folds run along `direction` (integer, in (u, v)) at `degrees` from u; the
/// lookup is `scale` * [[q, -p], [p, q]] for direction (p, q).
struct FoldOrientation {
  int p, q, scale;
  double degrees;
};
const std::array<FoldOrientation, kFoldOrientations>& foldOrientations();

/// The folds' angle from u (radians, in (-pi/2, pi/2]): half the fold axis's double angle, with
/// kFoldAxisBias taken off its first component (where no direction is preferred: folds along v).
double foldAngle(const Eigen::Vector2f& fold_axis);
/// The two orientations either side of the fold axis's angle and their weights (summing to 1).
struct FoldBlend {
  int first = 0, second = 1;
  float first_weight = 1.0f, second_weight = 0.0f;
};
FoldBlend foldOrientationBlend(const Eigen::Vector2f& fold_axis);

/// Tile coordinate of orientation k at patch coordinate (u, v), and the factor its heights are
/// scaled by (1 / tiles per patch across its folds).
Eigen::Vector2d foldTileCoordinate(int orientation, const Eigen::Vector2d& uv);
double foldHeightScale(int orientation);
/// How much of the strong (Y-Y) tile shows at a wrinkle strength, the rest being I: smoothstep.
float strongPatternWeight(float strength);

/// The two tiles, each a wrinkle map square in space (so its slopes turn with the lookups) whose
/// folds run along its v. Throws std::invalid_argument when their sizes differ or are empty.
struct FoldTiles {
  FoldTiles(ReliefMap slight, ReliefMap strong);
  ReliefMap slight;  ///< I folds
  ReliefMap strong;  ///< Y-Y chain
};

/// The relief drawn at patch coordinate `uv` with the vertex attributes interpolated there:
/// height (map units, for a tile one patch across) and slope (the tiles' physical slope, in the
/// patch's (u, v) directions), scaled by `strength`.
ReliefSample orientedFolds(const FoldTiles& tiles, const Eigen::Vector2d& uv, const Eigen::Vector2f& fold_axis,
                           float strength);

/// The relief drawn where the fold tile's coordinates follow the folds (fold_coordinates.h): the
/// tiles read at tile coordinate `tile` as they are, the slope turned back from the tile's x
/// (across the folds) and y (along `direction`, the folds' signed direction in (u, v)) to the
/// patch's (u, v); height in map units for a tile 1 / kFoldTilesPerPatch of a patch across, scaled
/// by `strength` (the strong tile's share as in orientedFolds). relief_surface.frag
/// (FOLD_COORDINATES) transcribes this one.
ReliefSample foldCoordinateRelief(const FoldTiles& tiles, const Eigen::Vector2d& tile, const Eigen::Vector2f& direction,
                                  float strength);

/// Both tiles' mip chains (buildMipChain), for lookups filtered to a sample spacing.
struct FoldTileMips {
  std::vector<ReliefMap> slight, strong;
};
FoldTileMips buildFoldTileMips(const FoldTiles& tiles);

/// orientedFolds from the tiles' mip chains, filtered for samples `uv_spacing` apart in patch
/// coordinates (displaced geometry's vertices, 1 / tessellation level): each orientation reads
/// its tiles at the level whose texels are as far apart as the samples are in its lookup, as a
/// texture unit does per pixel, so folds finer than the samples fade instead of aliasing.
/// `uv_spacing` 0 reads level 0: orientedFolds(FoldTiles).
ReliefSample orientedFolds(const FoldTileMips& mips, const Eigen::Vector2d& uv, const Eigen::Vector2f& fold_axis,
                           float strength, double uv_spacing);

/// foldCoordinateRelief from the tiles' mip chains, filtered for samples `uv_spacing` apart in
/// patch coordinates, as orientedFolds(FoldTileMips) filters.
ReliefSample foldCoordinateRelief(const FoldTileMips& mips, const Eigen::Vector2d& tile, const Eigen::Vector2f& direction,
                                  float strength, double uv_spacing);

/// The texture the shader samples: per pixel the slight tile's normal x, y then the strong
/// tile's, each (n + 1) / 2 * 255 (z is sqrt(1 - x^2 - y^2), n_z > 0). RGBA, row-major.
std::vector<std::uint8_t> encodeFoldTilesRgba(const FoldTiles& tiles);
/// encodeFoldTilesRgba of every level of both tiles' mip chains (buildMipChain; the normals of
/// the box-filtered heights, see EncodedNormalMap).
EncodedNormalMap encodeFoldTilesMips(const FoldTiles& tiles);

}  // namespace dressed_human
