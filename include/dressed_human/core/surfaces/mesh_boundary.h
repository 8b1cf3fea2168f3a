// Open boundaries of an indexed triangle mesh: edges used by one triangle only, chained into
// loops (a skirt has 2: waist and hem; pants 3: waist and two cuffs).
#pragma once

#include "dressed_human/core/surfaces/tessellation.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dressed_human {

// Each loop as its vertex indices in order. Throws std::runtime_error if the boundary edges do
// not form simple closed loops (a vertex with more than two boundary edges).
std::vector<std::vector<std::uint32_t>> boundaryLoops(const TriangleMesh& mesh);

// Connected components of the triangles of the given patches (all patches if empty), by shared
// vertices.
std::size_t connectedComponents(const TriangleMesh& mesh, const std::vector<std::uint32_t>& patches = {});

}  // namespace dressed_human
