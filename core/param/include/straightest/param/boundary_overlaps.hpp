// boundary_overlaps.hpp — does a map's boundary cross itself in the plane? A map with no flipped and
// no degenerate triangle can still be non-injective when its boundary overlaps itself (a free
// boundary can wrap around); a texture is then sampled twice. Counts the pairs of boundary edges,
// over every boundary loop, that cross or touch without sharing a vertex (or an end at the very same uv:
// parameterize's real faces of a filled disk split a vertex where they only meet at a point) (a sort-and-sweep on x, so
// near-linear in the number of boundary edges for a boundary that does not overlap).
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest {

int64_t boundaryOverlaps(const TriMesh& mesh, const std::vector<Vec2>& uv);

}  // namespace straightest
