// polygon_triangulation.hpp — splitting one planar-ish polygon of a mesh file into triangles.
// Geometry, not parsing: the readers hand it each face with more than three corners.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/base/vec3.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

/// Splits one polygon (indices into positions) into triangles by ear clipping in its Newell plane,
/// keeping the polygon's winding; falls back to a fan when the polygon is too degenerate to clip (or
/// has more than 256 corners: ear clipping is quadratic). Appends polygon.size() − 2 triangles to `out`
/// (none for fewer than 3 corners).
void triangulatePolygon(const std::vector<Vec3>& positions, const std::vector<int32_t>& polygon,
                        std::vector<Triangle>& out);

}  // namespace straightest
