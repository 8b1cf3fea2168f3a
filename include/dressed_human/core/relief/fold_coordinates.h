// Fold coordinates (issue 40): a garment's fold tile laid along its fold direction field, as one
// tile coordinate per point of the surface, instead of fixed orientations cross-faded
// (oriented_folds.h).
//
// Why. Cross-fading the two fixed orientations either side of the folds' angle mixes two patterns
// of unrelated phase wherever that angle turns, a few pixels at a time at the distances users look
// from: at 2.5 m the creases measured 0.35 (bench/relief_distance.py's crease sharpness), one
// orientation alone 0.24, a smooth sinusoid of the same period 0.23. Tile coordinates whose
// gradient follows the field draw one pattern that bends with it: nothing to fade.
//
// What. On a fixed grid of each patch (kGridLevel cells a side, the same whatever level of detail
// draws it), coordinates w = (across, along) with, over every grid edge du (in the patch's u, v),
//   w_b - w_a ~ kFoldTilesPerPatch (d_perp . du, d . du)
// for the fold direction d there (VertexStretch::fold_axis's angle, with kFoldAxisBias where no
// direction is preferred; d_perp = (d_v, -d_u), as orientation (1, 0) lays the tile out), in the
// least-squares sense, each edge weighted by its wrinkle strength plus kBaseWeight, so the folds
// are right where they show. A fold axis is a direction, not a vector (d and -d are the same
// folds), but coordinates need one of them: directions are signed to agree with their neighbours
// (breadth first from the most compressed node) and, from the second solve on, with their own
// previous sign, so that a sign never flips between frames. Around a closed sleeve the along-fold
// coordinate cannot grow all the way round; the least squares spread that, which only stretches
// the Y-Y chains along their folds.
//
// Time. Each solve starts from the last one (conjugate gradients) and is held to it by kHold, so
// the folds stick to the cloth as the pose changes; the first solve runs to convergence, and a
// pose held still converges to the least squares whatever the hold.
//
// A renderer reads w and d per vertex (sample): the fold tile at w, its slope turned back along
// d (relief_surface.frag, FOLD_COORDINATES; foldCoordinateRelief in oriented_folds.h).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/surfaces/patch_corner_split.h"
#include "dressed_human/core/surfaces/tessellation.h"

namespace dressed_human {

class FoldCoordinates {
 public:
  /// Cells a side of each patch's grid (about 5 cm on the default garments, half a fold tile):
  /// at 2.5 m the creases measured 0.258 at 4, 0.248 at 6 and 0.251 at 8 (bench/relief_distance.py).
  static constexpr int kGridLevel = 6;
  /// Edge weight added to the wrinkle strength: where nothing is compressed the coordinates still
  /// follow the (biased) field, smoothly.
  static constexpr float kBaseWeight = 0.05f;
  /// Pull of each node towards its previous solution, against edge weights of kBaseWeight .. 1 a
  /// neighbour: the folds stick to the cloth and follow a changing field over a few frames.
  /// Walking, the relief at a point of the skirt then changes by 0.36 of its slope a frame (0.74 at
  /// a pull of 0.01; the fixed orientations 0.40), test_fold_coordinates.
  static constexpr float kHold = 3.0f;
  static constexpr float kFirstHold = 1e-4f;
  /// Conjugate gradient iterations of a first solve, and of every later one by default (from the
  /// last solution: walking, within a tenth of a tile of the converged solution; a pose held
  /// still converges over its frames).
  static constexpr int kFirstIterations = 400;
  static constexpr int kIterations = 8;

  /// `grid`: the garment tessellated at kGridLevel on every patch; `split`: its corner split
  /// (splitPatchCorners). Throws std::invalid_argument when a patch's grid is incomplete.
  void prepare(const TriangleMesh& grid, const PatchCornerSplit& split);
  bool prepared() const { return !nodes_.empty(); }
  /// The next solve starts over, as the first did (after frames without solves: the last
  /// solution belongs to another pose).
  void restart() { solved_ = false; }
  std::size_t nodeCount() const { return tiles_.size(); }

  /// From the posed grid's fold axes and wrinkle strengths (VertexCompression::evaluate), one
  /// per grid vertex. Throws std::invalid_argument naming wrong counts or an unprepared grid.
  void solve(const std::vector<Eigen::Vector2f>& fold_axes, const std::vector<float>& strengths,
             int iterations = kIterations);

  /// At (u, v) of `patch`: bilinear in the patch's grid cell; the direction is unit length.
  Eigen::Vector2f tileCoordinate(std::uint32_t patch, const Eigen::Vector2f& uv) const;
  Eigen::Vector2f direction(std::uint32_t patch, const Eigen::Vector2f& uv) const;
  /// Per vertex of `mesh` (its own patch and (u, v)): resized, no allocation once sized. Throws
  /// std::invalid_argument before the first solve or for a patch the grid does not have.
  void sample(const TriangleMesh& mesh, std::vector<Eigen::Vector2f>& tiles,
              std::vector<Eigen::Vector2f>& directions) const;

  /// Per grid vertex, for tests and probes.
  const std::vector<Eigen::Vector2f>& nodeTiles() const { return tiles_; }
  const std::vector<Eigen::Vector2f>& nodeDirections() const { return directions_; }

 private:
  struct Edge {
    std::uint32_t a, b;
    Eigen::Vector2f du;  // (u, v) from a to b in their triangle's patch
  };
  template <typename F>
  Eigen::Vector2f bilinear(std::uint32_t patch, const Eigen::Vector2f& uv, const F& value) const;
  void signDirections(const std::vector<Eigen::Vector2f>& fold_axes, const std::vector<float>& strengths);
  void applyMatrix(const std::vector<Eigen::Vector2f>& x, std::vector<Eigen::Vector2f>& y) const;

  std::vector<std::uint32_t> nodes_;  // per patch, (kGridLevel + 1)^2 grid vertices, row by row
  std::vector<Edge> edges_;
  std::vector<std::vector<std::uint32_t>> neighbours_;
  std::vector<float> edge_weight_;
  std::vector<Eigen::Vector2f> tiles_, directions_;
  bool solved_ = false;
  float hold_ = kFirstHold;
  // Scratch, sized once.
  std::vector<Eigen::Vector2f> rhs_, residual_, search_, product_;
  std::vector<std::uint32_t> queue_;
  std::vector<char> signed_;
};

}  // namespace dressed_human
