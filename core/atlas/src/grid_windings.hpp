// grid_windings.hpp — every face of the placed atlas wound as its chart on the 2^-24 grid the check measures on
// (and float32 holds exactly), needle faces included.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas_detail {

/// Mends each face of a chart (chartOfFace ≥ 0) that the grid sees turned over, or flat though it has area
/// and no certain winding in double precision: one of its corners, with every corner of the chart at the
/// same vertex and uv, moves onto a grid point at most two steps from its own where all their faces wind as
/// the chart does. Faces that wind right are not touched; corners that are not finite neither.
void mendGridWindings(const TriMesh& mesh, const std::vector<int32_t>& chartOfFace, std::vector<Vec2>& cornerUv);

}  // namespace straightest::atlas_detail
