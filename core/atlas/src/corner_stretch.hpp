// corner_stretch.hpp — Sander et al.'s texture stretch of faces mapped per corner (texture_stretch.hpp's
// definitions, for a chart's or a whole atlas's corner uv rather than one uv per vertex).
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

struct CornerStretch {
  double l2 = 1, linf = 1;  // normalized to equal total area; +inf when a face is flipped or degenerate
  int64_t flipped = 0;      // uv triangles with area <= kDegenerateUV × the mean (clockwise or flat)
};

/// faces[i] is mapped to cornerUv[3i + k] at its corner k.
CornerStretch cornerStretch(const TriMesh& mesh, const std::vector<int32_t>& faces, const std::vector<Vec2>& cornerUv);

/// Twice the signed area of the uv triangle of face i.
inline double twiceUvArea(const std::vector<Vec2>& cornerUv, size_t i) {
  return cross(cornerUv[3 * i + 1] - cornerUv[3 * i], cornerUv[3 * i + 2] - cornerUv[3 * i]);
}

}  // namespace straightest::atlas
