#include "dressed_human/core/relief/fold_coordinates.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dressed_human/core/relief/oriented_folds.h"

namespace dressed_human {
namespace {

constexpr int kSide = FoldCoordinates::kGridLevel + 1;
constexpr std::uint32_t kMissing = 0xffffffffu;

// The folds' direction at a node as the renderer reads it: the fold axis is a double angle.
Eigen::Vector2f foldDirection(const Eigen::Vector2f& fold_axis) {
  const double angle = foldAngle(fold_axis);
  return Eigen::Vector2d(std::cos(angle), std::sin(angle)).cast<float>();
}

float sum(const std::vector<Eigen::Vector2f>& a, const std::vector<Eigen::Vector2f>& b, int k) {
  float total = 0.0f;
  for (std::size_t i = 0; i < a.size(); ++i) total += a[i][k] * b[i][k];
  return total;
}

}  // namespace

void FoldCoordinates::prepare(const TriangleMesh& grid, const PatchCornerSplit& split) {
  if (split.uv.size() != split.source.size() || split.patch.size() != split.source.size()) {
    throw std::invalid_argument("fold coordinates: the corner split's sizes do not match");
  }
  std::uint32_t patches = 0;
  for (const std::uint32_t patch : grid.triangle_patch) patches = std::max(patches, patch + 1);
  nodes_.assign(static_cast<std::size_t>(patches) * kSide * kSide, kMissing);
  for (std::size_t c = 0; c < split.source.size(); ++c) {
    const int i = static_cast<int>(std::lround(split.uv[c].x() * FoldCoordinates::kGridLevel));
    const int j = static_cast<int>(std::lround(split.uv[c].y() * FoldCoordinates::kGridLevel));
    if (i < 0 || j < 0 || i >= kSide || j >= kSide || split.patch[c] >= patches) continue;
    nodes_[(static_cast<std::size_t>(split.patch[c]) * kSide + static_cast<std::size_t>(j)) * kSide +
           static_cast<std::size_t>(i)] = split.source[c];
  }
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n] == kMissing) {
      const std::size_t patch = n / (kSide * kSide);
      nodes_.clear();
      throw std::invalid_argument("fold coordinates: patch " + std::to_string(patch) + " has no grid vertex at (" +
                                  std::to_string(n % kSide) + ", " + std::to_string(n / kSide % kSide) +
                                  ") / " + std::to_string(kGridLevel) + ": not a grid at level " +
                                  std::to_string(kGridLevel));
    }
  }
  const std::size_t vertices = grid.vertexCount();
  edges_.clear();
  neighbours_.assign(vertices, {});
  for (std::size_t t = 0; t + 2 < split.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t from = split.indices[t + k], to = split.indices[t + (k + 1) % 3];
      const std::uint32_t a = split.source[from], b = split.source[to];
      if (a == b) continue;  // a welded pole
      // Once per edge (two triangles share it, both give it the same (u, v) difference).
      edges_.push_back(a < b ? Edge{a, b, split.uv[to] - split.uv[from]} : Edge{b, a, split.uv[from] - split.uv[to]});
    }
  }
  std::sort(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  edges_.erase(std::unique(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) { return x.a == y.a && x.b == y.b; }),
               edges_.end());
  for (const Edge& edge : edges_) {
    if (edge.a >= vertices || edge.b >= vertices) throw std::invalid_argument("fold coordinates: a split vertex beyond the grid");
    neighbours_[edge.a].push_back(edge.b);
    neighbours_[edge.b].push_back(edge.a);
  }
  edge_weight_.assign(edges_.size(), 0.0f);
  tiles_.assign(vertices, Eigen::Vector2f::Zero());
  directions_.assign(vertices, Eigen::Vector2f::Zero());
  rhs_ = residual_ = search_ = product_ = tiles_;
  signed_.assign(vertices, 0);
  queue_.reserve(vertices);
  solved_ = false;
}

// Signs: the previous solve's where there is one, else agreeing with a signed neighbour, breadth
// first from the most compressed node.
void FoldCoordinates::signDirections(const std::vector<Eigen::Vector2f>& fold_axes,
                                     const std::vector<float>& strengths) {
  const std::size_t vertices = directions_.size();
  if (solved_) {
    for (std::size_t v = 0; v < vertices; ++v) {
      const Eigen::Vector2f d = foldDirection(fold_axes[v]);
      directions_[v] = d.dot(directions_[v]) < 0.0f ? Eigen::Vector2f(-d) : d;
    }
    return;
  }
  std::fill(signed_.begin(), signed_.end(), 0);
  for (;;) {
    std::uint32_t root = kMissing;
    for (std::uint32_t v = 0; v < vertices; ++v) {
      if (!signed_[v] && (root == kMissing || strengths[v] > strengths[root])) root = v;
    }
    if (root == kMissing) return;
    directions_[root] = foldDirection(fold_axes[root]);
    signed_[root] = 1;
    queue_.assign(1, root);
    for (std::size_t q = 0; q < queue_.size(); ++q) {
      const std::uint32_t v = queue_[q];
      for (const std::uint32_t n : neighbours_[v]) {
        if (signed_[n]) continue;
        const Eigen::Vector2f d = foldDirection(fold_axes[n]);
        directions_[n] = d.dot(directions_[v]) < 0.0f ? Eigen::Vector2f(-d) : d;
        signed_[n] = 1;
        queue_.push_back(n);
      }
    }
  }
}

// (edge Laplacian + kHold) x: the normal equations of the least squares.
void FoldCoordinates::applyMatrix(const std::vector<Eigen::Vector2f>& x, std::vector<Eigen::Vector2f>& y) const {
  for (std::size_t v = 0; v < x.size(); ++v) y[v] = hold_ * x[v];
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Eigen::Vector2f difference = edge_weight_[e] * (x[edges_[e].b] - x[edges_[e].a]);
    y[edges_[e].b] += difference;
    y[edges_[e].a] -= difference;
  }
}

void FoldCoordinates::solve(const std::vector<Eigen::Vector2f>& fold_axes, const std::vector<float>& strengths,
                            int iterations) {
  if (!prepared()) throw std::invalid_argument("fold coordinates: solve() before prepare()");
  if (fold_axes.size() != tiles_.size() || strengths.size() != tiles_.size()) {
    throw std::invalid_argument("fold coordinates: " + std::to_string(fold_axes.size()) + " fold axes and " +
                                std::to_string(strengths.size()) + " strengths for a grid of " +
                                std::to_string(tiles_.size()) + " vertices");
  }
  signDirections(fold_axes, strengths);
  // Right-hand side: each edge's wanted difference, and the hold towards the last solution (at the
  // first, towards 0 only enough to fix the free constant).
  hold_ = solved_ ? kHold : kFirstHold;
  for (std::size_t v = 0; v < tiles_.size(); ++v) rhs_[v] = hold_ * tiles_[v];
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Edge& edge = edges_[e];
    Eigen::Vector2f d = directions_[edge.a] + directions_[edge.b];
    d = d.squaredNorm() > 1e-12f ? Eigen::Vector2f(d.normalized()) : directions_[edge.a];
    const Eigen::Vector2f wanted =
        static_cast<float>(kFoldTilesPerPatch) * Eigen::Vector2f(d.y() * edge.du.x() - d.x() * edge.du.y(), d.dot(edge.du));
    edge_weight_[e] = 0.5f * (strengths[edge.a] + strengths[edge.b]) + kBaseWeight;
    rhs_[edge.b] += edge_weight_[e] * wanted;
    rhs_[edge.a] -= edge_weight_[e] * wanted;
  }
  // Conjugate gradients for both coordinates at once (they do not couple), from the last solution.
  applyMatrix(tiles_, product_);
  for (std::size_t v = 0; v < tiles_.size(); ++v) residual_[v] = rhs_[v] - product_[v];
  search_ = residual_;
  Eigen::Vector2f rr(sum(residual_, residual_, 0), sum(residual_, residual_, 1));
  const int steps = solved_ ? iterations : std::max(iterations, kFirstIterations);
  for (int step = 0; step < steps; ++step) {
    applyMatrix(search_, product_);
    Eigen::Vector2f alpha = Eigen::Vector2f::Zero();
    for (int k = 0; k < 2; ++k) {
      const float curvature = sum(search_, product_, k);
      alpha[k] = curvature > 0.0f ? rr[k] / curvature : 0.0f;
    }
    for (std::size_t v = 0; v < tiles_.size(); ++v) {
      tiles_[v] += alpha.cwiseProduct(search_[v]);
      residual_[v] -= alpha.cwiseProduct(product_[v]);
    }
    const Eigen::Vector2f next(sum(residual_, residual_, 0), sum(residual_, residual_, 1));
    for (std::size_t v = 0; v < tiles_.size(); ++v) {
      for (int k = 0; k < 2; ++k) search_[v][k] = residual_[v][k] + (rr[k] > 0.0f ? next[k] / rr[k] : 0.0f) * search_[v][k];
    }
    rr = next;
  }
  solved_ = true;
}

template <typename F>
Eigen::Vector2f FoldCoordinates::bilinear(std::uint32_t patch, const Eigen::Vector2f& uv, const F& value) const {
  const std::size_t patches = nodes_.size() / (kSide * kSide);
  if (patch >= patches) {
    throw std::invalid_argument("fold coordinates: patch " + std::to_string(patch) + " of " + std::to_string(patches));
  }
  const Eigen::Vector2f scaled = uv.cwiseMax(0.0f).cwiseMin(1.0f) * static_cast<float>(kGridLevel);
  const int i = std::min(static_cast<int>(scaled.x()), kGridLevel - 1);
  const int j = std::min(static_cast<int>(scaled.y()), kGridLevel - 1);
  const float s = scaled.x() - static_cast<float>(i), t = scaled.y() - static_cast<float>(j);
  const auto at = [&](int di, int dj) {
    return value(nodes_[(static_cast<std::size_t>(patch) * kSide + static_cast<std::size_t>(j + dj)) * kSide +
                        static_cast<std::size_t>(i + di)]);
  };
  return (1.0f - t) * ((1.0f - s) * at(0, 0) + s * at(1, 0)) + t * ((1.0f - s) * at(0, 1) + s * at(1, 1));
}

Eigen::Vector2f FoldCoordinates::tileCoordinate(std::uint32_t patch, const Eigen::Vector2f& uv) const {
  return bilinear(patch, uv, [this](std::uint32_t node) { return tiles_[node]; });
}

Eigen::Vector2f FoldCoordinates::direction(std::uint32_t patch, const Eigen::Vector2f& uv) const {
  const Eigen::Vector2f d = bilinear(patch, uv, [this](std::uint32_t node) { return directions_[node]; });
  return d.squaredNorm() > 1e-12f ? Eigen::Vector2f(d.normalized()) : Eigen::Vector2f(0.0f, 1.0f);
}

void FoldCoordinates::sample(const TriangleMesh& mesh, std::vector<Eigen::Vector2f>& tiles,
                             std::vector<Eigen::Vector2f>& directions) const {
  if (!solved_) throw std::invalid_argument("fold coordinates: sample() before solve()");
  tiles.resize(mesh.vertexCount());
  directions.resize(mesh.vertexCount());
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    tiles[v] = tileCoordinate(mesh.vertex_patch[v], mesh.uv[v]);
    directions[v] = direction(mesh.vertex_patch[v], mesh.uv[v]);
  }
}

}  // namespace dressed_human
