// Displaced geometry: the relief map's heights moved into the mesh itself, the reference that
// bump mapping approximates (issue 7's "displaced geometry" relief mode, issue 8's comparison).
// Bump mapping only tilts normals; displacement moves vertices along the normal by the relief
// height, so silhouettes and self-occlusion change too, at the cost of a fine tessellation.
//
// Units. The relief tile covers `tiling` x `tiling` tiles per patch (uv in [0, 1] per patch, as
// the shader's reliefUv = uv * tiling). Map heights are in units where one tile is
// 1 / height_to_tile long (skin maps: tile units, height_to_tile = 1; wrinkle maps: buckling
// cell units, see wrinkle_map.h), slopes are dimensionless. A tile is mapped onto a piece of
// surface sqrt(|F_u| |F_v|) / tiling metres across, so the displacement in metres is
//   d = amplitude * height_to_tile * h * sqrt(|F_u| |F_v|) / tiling,
// and the displaced normal tilts by amplitude * slope, as the bump-mapping shader tilts it:
// the two relief modes agree where the surface is locally isometric to the tile.
#pragma once

#include "dressed_human/core/relief/oriented_folds.h"
#include "dressed_human/core/relief/relief_sample.h"
#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/surfaces/tessellation.h"

namespace dressed_human {

struct ReliefDisplacement {
  const ReliefMap* map = nullptr;  ///< not owned; must outlive the call
  float tiling = 1.0f;             ///< tiles per patch along u and v, > 0
  float height_to_tile = 1.0f;     ///< tile units per map height unit, > 0
  float amplitude = 1.0f;          ///< relief strength (as the shader's), >= 0
  /// Optional per-vertex factor on the amplitude (SurfacePart::relief_weight); null: 1.
  const std::vector<float>* weights = nullptr;
  /// Garments: the fold tiles (oriented_folds.h) drawn instead of `map`, turned by the vertices'
  /// fold axes (SurfacePart::fold_axis; null: none preferred) and patterned by `weights` as the
  /// shader does; heights are then for a tile one patch across (tiling must be 1).
  const FoldTiles* folds = nullptr;
  const std::vector<Eigen::Vector2f>* fold_axes = nullptr;
  /// Garments with fold coordinates (fold_coordinates.h; SurfacePart's CpuVertices::fold_tile and
  /// fold_direction, both or neither): the tiles laid by them (foldCoordinateRelief) instead.
  const std::vector<Eigen::Vector2f>* fold_tiles = nullptr;
  const std::vector<Eigen::Vector2f>* fold_directions = nullptr;
  /// Optional filtering, so relief finer than the vertices fades instead of aliasing: the mip
  /// chain of `map` (buildMipChain; of `folds`: buildFoldTileMips) and each patch's tessellation
  /// level (vertices 1 / level apart in patch coordinates). Each vertex then reads the relief at
  /// the level whose texels are as far apart as the vertices, as a texture unit does per pixel.
  /// Null: the maps are sampled as they are.
  const std::vector<ReliefMap>* map_mips = nullptr;
  const FoldTileMips* fold_mips = nullptr;
  const std::vector<int>* patch_levels = nullptr;
  /// Optional: per patch, tiles along u and along v (SurfacePart::relief_tiles, whole numbers
  /// >= 1), in place of `tiling`; vertices read theirs through the mesh's vertex_patch.
  const std::vector<Eigen::Vector2f>* patch_tiles = nullptr;
};

/// Height and slopes of the map at tile coordinates (any real values: the map wraps),
/// bilinear between pixel centres.
ReliefSample sampleReliefMap(const ReliefMap& map, double tile_u, double tile_v);

/// The same from a mip chain (buildMipChain), for samples `texels_per_sample` level-0 texels
/// apart: at level log2(texels_per_sample), blended between the two nearest levels (the last one
/// beyond the chain, level 0 below one texel). Throws std::invalid_argument for an empty chain.
ReliefSample sampleReliefLevels(const std::vector<ReliefMap>& levels, double tile_u, double tile_v,
                                double texels_per_sample);

/// Throws std::invalid_argument naming a bad field (no map, empty map, tiling or
/// height_to_tile <= 0, negative or non-finite amplitude, fold tiles with a tiling other than 1,
/// mip chains without patch levels or not of the map they go with).
void checkReliefDisplacement(const ReliefDisplacement& displacement);

/// `out` = `base` with every vertex moved along its normal and normals tilted by the relief
/// (tangents and uv copied). Allocation-free once `out` has had the same size. Throws as
/// checkReliefDisplacement, or when `weights` or `fold_axes` does not have one entry per vertex,
/// or a vertex's patch has no level in `patch_levels` (or a level below 1).
void displaceMesh(const TriangleMesh& base, const ReliefDisplacement& displacement, TriangleMesh& out);

}  // namespace dressed_human
