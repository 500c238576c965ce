// cut_open.hpp — a surface cut open along a seam of its edges: every seam vertex is copied once per
// wedge of faces the seam separates around it (seam-degree d ≥ 2 → d copies; an end of the seam, d = 1,
// and every other vertex keep one), so each seam edge becomes two boundary edges.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "straightest/base/progress.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest::detail {

struct CutOpen {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;  // the surface's faces in its order, corners replaced by their copies
  std::vector<int32_t> copyOf;      // per new vertex: the surface vertex it copies
};

/// Copies are numbered in the order of the vertices they copy (so with no seam nothing moves), a vertex's
/// copies counter-clockwise around it from a seam edge. Unreferenced vertices are dropped. Progress in
/// `stage`'s 0..1; nothing (nullopt) when cancelled.
std::optional<CutOpen> cutOpen(const TriMesh& surface, const std::vector<std::array<int32_t, 2>>& seam,
                               const Progress& progress, const char* stage);

}  // namespace straightest::detail
