#include "dressed_human/core/surfaces/mesh_boundary.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <utility>

namespace dressed_human {

std::vector<std::vector<std::uint32_t>> boundaryLoops(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = mesh.indices[t + k];
      std::uint32_t b = mesh.indices[t + (k + 1) % 3];
      if (a > b) std::swap(a, b);
      ++count[{a, b}];
    }
  }
  std::map<std::uint32_t, std::vector<std::uint32_t>> next;
  for (const auto& [edge, n] : count) {
    if (n != 1) continue;
    next[edge.first].push_back(edge.second);
    next[edge.second].push_back(edge.first);
  }
  for (const auto& [v, list] : next) {
    if (list.size() != 2)
      throw std::runtime_error("boundaryLoops: vertex " + std::to_string(v) + " has " + std::to_string(list.size()) +
                               " boundary edges");
  }
  std::set<std::uint32_t> seen;
  std::vector<std::vector<std::uint32_t>> loops;
  for (const auto& [start, list] : next) {
    if (seen.count(start)) continue;
    std::vector<std::uint32_t> loop = {start};
    seen.insert(start);
    std::uint32_t previous = start;
    std::uint32_t current = list[0];
    while (current != start) {
      loop.push_back(current);
      seen.insert(current);
      const std::vector<std::uint32_t>& n = next[current];
      const std::uint32_t following = n[0] == previous ? n[1] : n[0];
      previous = current;
      current = following;
    }
    loops.push_back(loop);
  }
  return loops;
}

std::size_t connectedComponents(const TriangleMesh& mesh, const std::vector<std::uint32_t>& patches) {
  std::vector<std::uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  const std::set<std::uint32_t> wanted(patches.begin(), patches.end());
  std::set<std::uint32_t> used;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!wanted.empty() && wanted.count(mesh.triangle_patch[t]) == 0) continue;
    const std::uint32_t a = mesh.indices[3 * t];
    for (int k = 0; k < 3; ++k) {
      used.insert(mesh.indices[3 * t + k]);
      parent[find(mesh.indices[3 * t + k])] = find(a);
    }
  }
  std::set<std::uint32_t> roots;
  for (std::uint32_t v : used) roots.insert(find(v));
  return roots.size();
}

}  // namespace dressed_human
