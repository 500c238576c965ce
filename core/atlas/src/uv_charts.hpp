// uv_charts.hpp — an atlas's charts as its uv alone defines them: faces joined across edges whose endpoints
// have the same snapped uv on both sides; and the seams, the edges that are not joined.
#pragma once
#include <cstdint>
#include <vector>

#include "snapped_uv.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas_detail {

struct UvCharts {
  std::vector<GridPoint> corner;     // per corner, snapped (unused where the face is not finite)
  std::vector<uint8_t> finiteFace;   // per face: all three uv finite
  std::vector<uint8_t> joined;       // per halfedge: glued to its twin in the uv
  std::vector<int32_t> chartOfFace;  // −1 for a face with a non-finite uv
  int32_t charts = 0;
  int64_t nonFiniteCorners = 0;
  int64_t seamEdges = 0;
  double seamLength = 0;
};

UvCharts findUvCharts(const TriMesh& mesh, const std::vector<Vec2>& cornerUv);

/// Halfedge h bounds its chart: no twin, or the twin's side has other uv.
inline bool isChartBoundary(const UvCharts& charts, int32_t h) { return charts.joined[h] == 0; }

}  // namespace straightest::atlas_detail
