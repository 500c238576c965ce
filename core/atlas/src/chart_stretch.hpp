// chart_stretch.hpp — each chart's winding (majority, flipped and degenerate faces) and Sander stretch.
#pragma once
#include <cstdint>
#include <vector>

#include "uv_charts.hpp"

namespace straightest::atlas_detail {

struct ChartStretch {
  double l2 = 0, linf = 0;  // whole atlas; inf when any face is flipped or degenerate, or a uv not finite
  std::vector<double> chartL2, chartLinf;
  int64_t flipped = 0, mirroredCharts = 0, degenerate = 0;
  double uvArea = 0;  // Σ |uv triangle area| of the finite faces, in [0,1]² units (uv as given)
};

/// Stretch of the uv as laid on texels: u scaled by texels.x (the atlas width), v by texels.y (its height).
ChartStretch measureChartStretch(const TriMesh& mesh, const std::vector<Vec2>& cornerUv, const UvCharts& charts,
                                 Vec2 texels);

}  // namespace straightest::atlas_detail
