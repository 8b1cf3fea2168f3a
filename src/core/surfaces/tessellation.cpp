#include "dressed_human/core/surfaces/tessellation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dressed_human {

namespace {

constexpr double kCollapsedRelative = 1e-9;
// Linked edges must coincide to this fraction of the larger patch scale. The check exists to
// catch a wrong topology (which would otherwise hide a gap behind shared vertices), not to
// grade C0 precision.
constexpr double kLinkMismatchRelative = 1e-6;

int edgeIndex(PatchEdge edge) { return static_cast<int>(edge); }

const char* edgeName(PatchEdge edge) {
  switch (edge) {
    case PatchEdge::kV0:
      return "v=0";
    case PatchEdge::kU1:
      return "u=1";
    case PatchEdge::kV1:
      return "v=1";
    case PatchEdge::kU0:
      return "u=0";
  }
  return "?";
}

// Edges are traversed counter-clockwise around the (u,v) square inside the tessellator, so that
// the patch interior is always on the left. v0 and u1 run along their parameter, v1 and u0 against.
bool runsAgainstParameter(int edge) { return edge >= 2; }

// (u, v) of point k of m on edge e, k counted counter-clockwise.
Eigen::Vector2d edgePointParameters(int edge, int k, int m) {
  const double t = static_cast<double>(k) / m;
  switch (edge) {
    case 0:
      return {t, 0.0};
    case 1:
      return {1.0, t};
    case 2:
      return {1.0 - t, 1.0};
    default:
      return {0.0, 1.0 - t};
  }
}

bool edgesCoincide(const std::array<Eigen::Vector3d, 4>& a, const std::array<Eigen::Vector3d, 4>& b, bool reversed,
                   double tolerance) {
  const double tolerance_squared = tolerance * tolerance;
  for (int k = 0; k < 4; ++k) {
    if (!((a[k] - b[reversed ? 3 - k : k]).squaredNorm() <= tolerance_squared)) return false;
  }
  return true;
}

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  // The smaller slot stays root so ownership does not depend on the order of the unions.
  if (a < b)
    parent[b] = a;
  else if (b < a)
    parent[a] = b;
}

}  // namespace

namespace {

// Point k of an edge, by increasing edge parameter, is control point first + k * step (4 j + i).
struct EdgeWalk {
  int first;
  int step;
};

EdgeWalk edgeWalk(PatchEdge edge) {
  switch (edge) {
    case PatchEdge::kV0:
      return {BezierPatch::index(0, 0), 1};
    case PatchEdge::kU1:
      return {BezierPatch::index(3, 0), 4};
    case PatchEdge::kV1:
      return {BezierPatch::index(0, 3), 1};
    default:
      return {BezierPatch::index(0, 0), 4};
  }
}

int edgePointIndex(PatchEdge edge, int k) {
  const EdgeWalk walk = edgeWalk(edge);
  return walk.first + k * walk.step;
}

// edgesCoincide on the patches' own points: this runs for every link every frame, so the edge
// is decoded once per link and the four points are walked with a stride.
bool linkedEdgesCoincide(const BezierPatch& a, PatchEdge edge_a, const BezierPatch& b, PatchEdge edge_b, bool reversed,
                         double tolerance) {
  const double tolerance_squared = tolerance * tolerance;
  const EdgeWalk walk_a = edgeWalk(edge_a);
  EdgeWalk walk_b = edgeWalk(edge_b);
  if (reversed) walk_b = {walk_b.first + 3 * walk_b.step, -walk_b.step};
  const Eigen::Vector3d* points_a = a.controlPoints().data() + walk_a.first;
  const Eigen::Vector3d* points_b = b.controlPoints().data() + walk_b.first;
  for (int k = 0; k < 4; ++k) {
    if (!((points_a[k * walk_a.step] - points_b[k * walk_b.step]).squaredNorm() <= tolerance_squared)) return false;
  }
  return true;
}

}  // namespace

std::array<Eigen::Vector3d, 4> edgeControlPoints(const BezierPatch& patch, PatchEdge edge) {
  std::array<Eigen::Vector3d, 4> points;
  for (int k = 0; k < 4; ++k)
    points[static_cast<std::size_t>(k)] = patch.controlPoints()[static_cast<std::size_t>(edgePointIndex(edge, k))];
  return points;
}

bool isCollapsed(const BezierPatch& patch, PatchEdge edge) {
  const double tolerance = kCollapsedRelative * patch.scale();
  const EdgeWalk walk = edgeWalk(edge);
  const Eigen::Vector3d* points = patch.controlPoints().data() + walk.first;
  for (int k = 1; k < 4; ++k) {
    if (!((points[k * walk.step] - points[0]).squaredNorm() <= tolerance * tolerance)) return false;
  }
  return true;
}

// ------------------------------------------------------------------------------- PatchTopology

PatchTopology::PatchTopology(std::size_t patch_count)
    : patch_count_(patch_count), edge_linked_(4 * patch_count, false) {}

bool PatchTopology::isLinked(std::uint32_t patch, PatchEdge edge) const {
  return patch < patch_count_ && edge_linked_[4 * patch + edgeIndex(edge)];
}

void PatchTopology::link(std::uint32_t patch_a, PatchEdge edge_a, std::uint32_t patch_b, PatchEdge edge_b,
                         bool reversed) {
  for (std::uint32_t patch : {patch_a, patch_b}) {
    if (patch >= patch_count_) {
      throw std::invalid_argument("PatchTopology::link: patch " + std::to_string(patch) + " does not exist (" +
                                  std::to_string(patch_count_) + " patches)");
    }
  }
  if (patch_a == patch_b && edge_a == edge_b) {
    throw std::invalid_argument("PatchTopology::link: edge " + std::string(edgeName(edge_a)) + " of patch " +
                                std::to_string(patch_a) + " linked to itself");
  }
  for (auto [patch, edge] : {std::pair{patch_a, edge_a}, std::pair{patch_b, edge_b}}) {
    if (edge_linked_[4 * patch + edgeIndex(edge)]) {
      throw std::invalid_argument("PatchTopology::link: edge " + std::string(edgeName(edge)) + " of patch " +
                                  std::to_string(patch) + " is already linked; an edge meets at most one other edge");
    }
  }
  edge_linked_[4 * patch_a + edgeIndex(edge_a)] = true;
  edge_linked_[4 * patch_b + edgeIndex(edge_b)] = true;
  links_.push_back(EdgeLink{patch_a, edge_a, patch_b, edge_b, reversed});
}

PatchTopology PatchTopology::fromCoincidentEdges(const std::vector<BezierPatch>& patches, double tolerance) {
  if (!(tolerance >= 0.0)) {
    throw std::invalid_argument("PatchTopology::fromCoincidentEdges: tolerance must be >= 0");
  }
  PatchTopology topology(patches.size());
  const std::size_t edge_count = 4 * patches.size();
  std::vector<std::array<Eigen::Vector3d, 4>> points(edge_count);
  std::vector<bool> collapsed(edge_count);
  for (std::size_t e = 0; e < edge_count; ++e) {
    const PatchEdge edge = static_cast<PatchEdge>(e % 4);
    points[e] = edgeControlPoints(patches[e / 4], edge);
    // Poles coincide with every other pole at the same place: they are not shared edges.
    collapsed[e] = isCollapsed(patches[e / 4], edge);
  }
  for (std::size_t a = 0; a < edge_count; ++a) {
    if (collapsed[a]) continue;
    for (std::size_t b = a + 1; b < edge_count; ++b) {
      if (collapsed[b]) continue;
      for (bool reversed : {false, true}) {
        if (!edgesCoincide(points[a], points[b], reversed, tolerance)) continue;
        topology.link(static_cast<std::uint32_t>(a / 4), static_cast<PatchEdge>(a % 4),
                      static_cast<std::uint32_t>(b / 4), static_cast<PatchEdge>(b % 4), reversed);
        break;
      }
    }
  }
  return topology;
}

// ------------------------------------------------------------------------------- error bounds

// Bound on |F - L| for the piecewise linear interpolant L on triangles spanning at most h = 1/n
// in u and in v. For a point x of a triangle with vertices p_k and barycentric weights l_k,
// F(x) - L(x) = -sum_k l_k R_k with the Taylor remainders |R_k| <= Q(p_k - x) / 2, where
// Q(d) = |d_u|^2 M_uu + 2 |d_u d_v| M_uv + |d_v|^2 M_vv bounds |F_dd| (M = sup of the second
// partials' norms). Using 2|d_u d_v| <= d_u^2 + d_v^2 and that the l-weighted variance of the
// vertices' u (and v) is at most h^2 / 4 gives |F - L| <= (M_uu + 2 M_uv + M_vv) h^2 / 8.
// ------------------------------------------------------------------------------- Tessellator

// A boundary vertex is evaluated once, by the first patch edge slot that reaches it.
struct Tessellator::OwnedBoundaryVertex {
  std::uint32_t vertex;
  std::uint32_t patch;
  double u;
  double v;
  const BernsteinWeights* u_weights;
  const BernsteinWeights* v_weights;
};

struct Tessellator::PatchLayout {
  int level;
  std::uint32_t interior_first_vertex;  // (level-1)^2 vertices, u fastest
  const BernsteinTable* interior;       // parameters k / level, k = 1..level-1
};

Tessellator::Tessellator() = default;
Tessellator::~Tessellator() = default;

const BernsteinTable& Tessellator::boundaryTable(int level) {
  if (boundary_tables_.size() <= static_cast<std::size_t>(level)) boundary_tables_.resize(level + 1);
  if (!boundary_tables_[level]) {
    boundary_tables_[level] = std::make_unique<BernsteinTable>(BernsteinTable::uniform(level));
  }
  return *boundary_tables_[level];
}

const BernsteinTable& Tessellator::interiorTable(int level) {
  if (interior_tables_.size() <= static_cast<std::size_t>(level)) interior_tables_.resize(level + 1);
  if (!interior_tables_[level]) {
    interior_tables_[level] = std::make_unique<BernsteinTable>(BernsteinTable::uniformInterior(level));
  }
  return *interior_tables_[level];
}

const TriangleMesh& Tessellator::tessellateUniform(const std::vector<BezierPatch>& patches,
                                                   const PatchTopology& topology, int level) {
  requested_levels_.assign(patches.size(), level);
  return tessellate(patches, topology, requested_levels_);
}

const TriangleMesh& Tessellator::tessellateToError(const std::vector<BezierPatch>& patches,
                                                   const PatchTopology& topology, double max_error, int max_level) {
  requested_levels_.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    requested_levels_[p] = levelForGeometricError(patches[p], max_error, max_level);
  }
  return tessellate(patches, topology, requested_levels_);
}

const TriangleMesh& Tessellator::tessellateForCamera(const std::vector<BezierPatch>& patches,
                                                     const PatchTopology& topology, const CameraView& camera,
                                                     double max_error_pixels, int max_level) {
  levelsForScreenError(patches, camera, max_error_pixels, max_level, requested_levels_);
  return tessellate(patches, topology, requested_levels_);
}

const TriangleMesh& Tessellator::tessellate(const std::vector<BezierPatch>& patches, const PatchTopology& topology,
                                            const std::vector<int>& levels) {
  prepareLayout(patches, topology, levels);
  evaluateVertices(patches);
  return mesh_;
}

const TriangleMesh& Tessellator::layout(const std::vector<BezierPatch>& patches, const PatchTopology& topology,
                                        const std::vector<int>& levels) {
  prepareLayout(patches, topology, levels);
  return mesh_;
}

void Tessellator::prepareLayout(const std::vector<BezierPatch>& patches, const PatchTopology& topology,
                                const std::vector<int>& levels) {
  if (topology.patchCount() != patches.size() || levels.size() != patches.size()) {
    throw std::invalid_argument("Tessellator: " + std::to_string(patches.size()) + " patches, but " +
                                std::to_string(topology.patchCount()) + " in the topology and " +
                                std::to_string(levels.size()) + " levels");
  }
  for (std::size_t p = 0; p < levels.size(); ++p) {
    if (levels[p] < 1 || levels[p] > kMaxLevel) {
      throw std::invalid_argument("Tessellator: level " + std::to_string(levels[p]) + " of patch " + std::to_string(p) +
                                  " is outside [1, " + std::to_string(kMaxLevel) + "]");
    }
  }
  for (const EdgeLink& link : topology.links()) {
    const BezierPatch& a = patches[link.patch_a];
    const BezierPatch& b = patches[link.patch_b];
    const double tolerance = kLinkMismatchRelative * std::max(a.scale(), b.scale());
    if (!linkedEdgesCoincide(a, link.edge_a, b, link.edge_b, link.reversed, tolerance)) {
      std::ostringstream message;
      message << "Tessellator: edge " << edgeName(link.edge_a) << " of patch " << link.patch_a << " and edge "
              << edgeName(link.edge_b) << " of patch " << link.patch_b << " are linked"
              << (link.reversed ? " (reversed)" : "") << " but their control points differ by more than " << tolerance;
      throw std::invalid_argument(message.str());
    }
  }
  collapsed_edges_.resize(4 * patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    for (int e = 0; e < 4; ++e) {
      collapsed_edges_[4 * p + e] = isCollapsed(patches[p], static_cast<PatchEdge>(e)) ? 1 : 0;
    }
  }
  if (!has_layout_ || layout_patch_count_ != patches.size() || layout_requested_levels_ != levels ||
      layout_collapsed_edges_ != collapsed_edges_ || !layoutMatches(topology)) {
    layout_requested_levels_ = levels;
    buildLayout(patches, topology);
  }
}

bool Tessellator::layoutMatches(const PatchTopology& topology) const { return layout_links_ == topology.links(); }

// Boundary slots: point k (counter-clockwise) of edge e of patch p; corners appear twice. Slots
// that are one point (a corner of two edges, a collapsed edge, two linked edges) are united.
struct Tessellator::BoundarySlots {
  std::vector<std::uint32_t> first;   // per patch edge its first slot; the slot count last
  std::vector<std::uint32_t> parent;  // union-find over the slots
  std::uint32_t operator()(std::size_t p, int e, int k) const {
    return first[4 * p + static_cast<std::size_t>(e)] + static_cast<std::uint32_t>(k);
  }
};

void Tessellator::buildLayout(const std::vector<BezierPatch>& patches, const PatchTopology& topology) {
  layout_patch_count_ = patches.size();
  layout_links_ = topology.links();
  layout_collapsed_edges_ = collapsed_edges_;
  ++layout_build_count_;
  static std::atomic<std::uint64_t> last_layout_id{0};
  layout_id_ = ++last_layout_id;

  const std::vector<int> edge_level = sharedEdgeLevels();
  giveLevelOnePatchesAnInnerVertex(edge_level);
  BoundarySlots slots = weldBoundarySlots(edge_level);
  const std::vector<std::uint32_t> slot_vertex = numberVertices(edge_level, slots);
  buildTriangles(edge_level, slots, slot_vertex);
  has_layout_ = true;
}

// Edge levels: the larger of the two patches' levels on a shared edge.
std::vector<int> Tessellator::sharedEdgeLevels() const {
  const std::size_t patch_count = layout_patch_count_;
  std::vector<int> edge_level(4 * patch_count);
  for (std::size_t p = 0; p < patch_count; ++p) {
    for (int e = 0; e < 4; ++e) edge_level[4 * p + e] = layout_requested_levels_[p];
  }
  for (const EdgeLink& link : layout_links_) {
    const int shared = std::max(layout_requested_levels_[link.patch_a], layout_requested_levels_[link.patch_b]);
    edge_level[4 * link.patch_a + edgeIndex(link.edge_a)] = shared;
    edge_level[4 * link.patch_b + edgeIndex(link.edge_b)] = shared;
  }
  return edge_level;
}

// A level-1 patch has no inner vertex to stitch a finer edge to: give it one.
void Tessellator::giveLevelOnePatchesAnInnerVertex(const std::vector<int>& edge_level) {
  levels_ = layout_requested_levels_;
  for (std::size_t p = 0; p < layout_patch_count_; ++p) {
    if (levels_[p] != 1) continue;
    for (int e = 0; e < 4; ++e) {
      if (edge_level[4 * p + e] > 1) levels_[p] = 2;
    }
  }
}

Tessellator::BoundarySlots Tessellator::weldBoundarySlots(const std::vector<int>& edge_level) const {
  const std::size_t patch_count = layout_patch_count_;
  BoundarySlots slot;
  slot.first.assign(4 * patch_count + 1, 0);
  for (std::size_t edge = 0; edge < 4 * patch_count; ++edge) {
    slot.first[edge + 1] = slot.first[edge] + static_cast<std::uint32_t>(edge_level[edge] + 1);
  }
  std::vector<std::uint32_t>& parent = slot.parent;
  parent.resize(slot.first.back());
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t p = 0; p < patch_count; ++p) {
    for (int e = 0; e < 4; ++e) {
      const int m = edge_level[4 * p + e];
      unite(parent, slot(p, e, m), slot(p, (e + 1) % 4, 0));  // corner shared by e and e + 1
      if (layout_collapsed_edges_[4 * p + e]) {
        for (int k = 1; k <= m; ++k) unite(parent, slot(p, e, 0), slot(p, e, k));
      }
    }
  }
  for (const EdgeLink& link : layout_links_) {
    const int ea = edgeIndex(link.edge_a);
    const int eb = edgeIndex(link.edge_b);
    const int m = edge_level[4 * link.patch_a + ea];
    for (int along = 0; along <= m; ++along) {  // index by increasing edge parameter of edge a
      const int along_b = link.reversed ? m - along : along;
      const int ka = runsAgainstParameter(ea) ? m - along : along;
      const int kb = runsAgainstParameter(eb) ? m - along_b : along_b;
      unite(parent, slot(link.patch_a, ea, ka), slot(link.patch_b, eb, kb));
    }
  }

  return slot;
}

// Vertex numbering: per patch its interior block, then the boundary vertices it owns. Returns
// the vertex of every boundary slot.
std::vector<std::uint32_t> Tessellator::numberVertices(const std::vector<int>& edge_level, BoundarySlots& slot) {
  const std::size_t patch_count = layout_patch_count_;
  const std::uint32_t slot_count = slot.first.back();
  std::vector<std::uint32_t>& parent = slot.parent;
  constexpr std::uint32_t kUnassigned = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> root_vertex(slot_count, kUnassigned);
  std::vector<std::uint32_t> slot_vertex(slot_count);
  patch_layouts_.resize(patch_count);
  owned_boundary_vertices_.clear();
  mesh_.uv.clear();
  mesh_.vertex_patch.clear();
  std::uint32_t vertex_count = 0;
  for (std::size_t p = 0; p < patch_count; ++p) {
    const int n = levels_[p];
    PatchLayout& layout = patch_layouts_[p];
    layout.level = n;
    layout.interior_first_vertex = vertex_count;
    layout.interior = &interiorTable(n);
    for (int j = 1; j < n; ++j) {
      for (int i = 1; i < n; ++i) {
        mesh_.uv.emplace_back(static_cast<float>(i) / n, static_cast<float>(j) / n);
        mesh_.vertex_patch.push_back(static_cast<std::uint32_t>(p));
      }
    }
    vertex_count += static_cast<std::uint32_t>((n - 1) * (n - 1));
    for (int e = 0; e < 4; ++e) {
      const int m = edge_level[4 * p + e];
      const BernsteinTable& table = boundaryTable(m);
      for (int k = 0; k <= m; ++k) {
        const std::uint32_t s = slot(p, e, k);
        const std::uint32_t root = findRoot(parent, s);
        if (root_vertex[root] == kUnassigned) {
          root_vertex[root] = vertex_count++;
          const Eigen::Vector2d uv = edgePointParameters(e, k, m);
          // Parameter k/m along the edge, or 1 - k/m = (m-k)/m, or exactly 0 or 1: all in `table`.
          auto weights_of = [&](double t) -> const BernsteinWeights* {
            if (t == 0.0) return &table.weights(0);
            if (t == 1.0) return &table.weights(m);
            return &table.weights(runsAgainstParameter(e) ? m - k : k);
          };
          owned_boundary_vertices_.push_back(OwnedBoundaryVertex{root_vertex[root], static_cast<std::uint32_t>(p),
                                                                 uv.x(), uv.y(), weights_of(uv.x()),
                                                                 weights_of(uv.y())});
          mesh_.uv.emplace_back(uv.cast<float>());
          mesh_.vertex_patch.push_back(static_cast<std::uint32_t>(p));
        }
        slot_vertex[s] = root_vertex[root];
      }
    }
  }
  // uv was appended in vertex order: interior blocks and owned vertices interleave the same way.
  mesh_.positions.resize(vertex_count);
  mesh_.normals.resize(vertex_count);
  mesh_.tangents_u.resize(vertex_count);
  mesh_.tangents_v.resize(vertex_count);

  return slot_vertex;
}

void Tessellator::buildTriangles(const std::vector<int>& edge_level, const BoundarySlots& slot,
                                 const std::vector<std::uint32_t>& slot_vertex) {
  const std::size_t patch_count = layout_patch_count_;
  mesh_.indices.clear();
  mesh_.triangle_patch.clear();
  corner_parameters_.clear();
  for (std::size_t p = 0; p < patch_count; ++p) {
    const int n = levels_[p];
    const std::uint32_t first = patch_layouts_[p].interior_first_vertex;
    struct Corner {
      std::uint32_t vertex;
      Eigen::Vector2d uv;
    };
    auto interior = [&](int i, int j) {
      return Corner{first + static_cast<std::uint32_t>((j - 1) * (n - 1) + (i - 1)),
                    Eigen::Vector2d(static_cast<double>(i) / n, static_cast<double>(j) / n)};
    };
    auto boundary = [&](int e, int k) {
      const int m = edge_level[4 * p + e];
      return Corner{slot_vertex[slot(p, e, k)], edgePointParameters(e, k, m)};
    };
    auto emit = [&](const Corner& a, const Corner& b, const Corner& c) {
      // Welded poles turn some triangles into segments: drop them.
      if (a.vertex == b.vertex || b.vertex == c.vertex || a.vertex == c.vertex) return;
      for (const Corner* corner : {&a, &b, &c}) {
        mesh_.indices.push_back(corner->vertex);
        corner_parameters_.push_back(corner->uv);
      }
      mesh_.triangle_patch.push_back(static_cast<std::uint32_t>(p));
    };

    if (n == 1) {  // every edge is level 1 here
      emit(boundary(0, 0), boundary(1, 0), boundary(2, 0));
      emit(boundary(0, 0), boundary(2, 0), boundary(3, 0));
      continue;
    }
    for (int j = 1; j + 1 < n; ++j) {
      for (int i = 1; i + 1 < n; ++i) {
        emit(interior(i, j), interior(i + 1, j), interior(i + 1, j + 1));
        emit(interior(i, j), interior(i + 1, j + 1), interior(i, j + 1));
      }
    }
    // Stitch each edge's vertices (m + 1, parameters k/m) to the side of the inner grid facing it
    // (n - 1 vertices, parameters (k+1)/n), walking both counter-clockwise and always advancing
    // the row whose next vertex comes first. With m >= n every triangle then spans at most 1/n
    // in u and in v, which geometricErrorBound relies on.
    for (int e = 0; e < 4; ++e) {
      const int m = edge_level[4 * p + e];
      auto inner = [&](int k) {  // k-th inner-ring vertex facing edge e, counter-clockwise
        switch (e) {
          case 0:
            return interior(1 + k, 1);
          case 1:
            return interior(n - 1, 1 + k);
          case 2:
            return interior(n - 1 - k, n - 1);
          default:
            return interior(1, n - 1 - k);
        }
      };
      int outer_k = 0;
      int inner_k = 0;
      const int inner_last = n - 2;
      while (outer_k < m || inner_k < inner_last) {
        // Next outer parameter (outer_k+1)/m against next inner (inner_k+2)/n, in integers.
        const bool advance_outer = inner_k == inner_last || (outer_k < m && static_cast<long>(outer_k + 1) * n <=
                                                                                static_cast<long>(inner_k + 2) * m);
        if (advance_outer) {
          emit(boundary(e, outer_k), boundary(e, outer_k + 1), inner(inner_k));
          ++outer_k;
        } else {
          emit(boundary(e, outer_k), inner(inner_k + 1), inner(inner_k));
          ++inner_k;
        }
      }
    }
  }
}

void Tessellator::evaluateVertices(const std::vector<BezierPatch>& patches) {
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const PatchLayout& layout = patch_layouts_[p];
    if (layout.level < 2) continue;
    const std::uint32_t first = layout.interior_first_vertex;
    patches[p].evaluateGrid(*layout.interior, *layout.interior,
                            SurfaceSampleArrays{&mesh_.positions[first], &mesh_.normals[first],
                                                &mesh_.tangents_u[first], &mesh_.tangents_v[first]});
  }
  for (const OwnedBoundaryVertex& owned : owned_boundary_vertices_) {
    const PatchSample sample = patches[owned.patch].sample(*owned.u_weights, owned.u, *owned.v_weights, owned.v);
    mesh_.positions[owned.vertex] = sample.position.cast<float>();
    mesh_.normals[owned.vertex] = sample.normal.cast<float>();
    mesh_.tangents_u[owned.vertex] = sample.d_du.cast<float>();
    mesh_.tangents_v[owned.vertex] = sample.d_dv.cast<float>();
  }
}

}  // namespace dressed_human
