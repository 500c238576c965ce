// chart_flattening.hpp — one chart mapped to the plane at its 3D scale, counter-clockwise, and judged:
// acceptable when bijective (no flipped or flat uv triangle, no crossing boundary) within the chart limits.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/atlas/chart_segmentation.hpp"

namespace straightest::atlas {

/// What makes a flat chart acceptable besides being bijective.
struct ChartLimits {
  double maxStretch = 1.02;  // Sander L2
  double minHullFill = 0;    // uv area / convex hull area (0: any shape)
};

struct ChartFlattening {
  FlatChart chart;
  bool acceptable = false;  // bijective and within the limits; a one-face chart always is
};

/// `faces` ascending and edge-connected. A lone face is laid out directly (a zero-area one as a thin
/// triangle along its longest edge, so its uv is finite and counter-clockwise); a planar chart is
/// projected onto its plane; any other is parameterized with the free boundary. The result always has
/// finite uv; when no map succeeds it is every face laid out on its own (not acceptable).
ChartFlattening flattenChart(const TriMesh& mesh, std::vector<int32_t> faces, const ChartLimits& limits,
                             const FreeBoundaryOptions& free);

}  // namespace straightest::atlas
