// chart_containment.cpp — every chart point tested exactly against the triangles of other charts that share
// its bucket. Coordinates are scaled by 6 so that edge midpoints and face centroids are grid points too.
#include "chart_containment.hpp"

#include <algorithm>
#include <cmath>

#include "bucket_grid.hpp"
#include "chart_boundaries.hpp"

namespace straightest::atlas_detail {

namespace {

constexpr int64_t kScale = 6;

/// A point to test, already scaled by kScale, and its chart.
struct ChartPoint {
  GridPoint p;
  int32_t chart;
};

/// The welded vertices, the midpoints of boundary edges (two charts overlapping along collinear boundary
/// edges show no crossing and may have no vertex strictly inside the other) and the face centroids (two
/// identical charts have neither).
std::vector<ChartPoint> chartPoints(const UvCharts& charts, const WeldedCharts& welded) {
  std::vector<ChartPoint> points;
  for (int32_t corner : welded.cornerOfVertex)
    points.push_back({charts.corner[corner] * kScale, charts.chartOfFace[corner / 3]});
  for (size_t f = 0; f < charts.chartOfFace.size(); ++f) {
    const int32_t chart = charts.chartOfFace[f];
    const GridPoint* q = &charts.corner[3 * f];
    if (chart < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const GridPoint &a = q[k], &b = q[(k + 1) % 3];
      if (isChartBoundary(charts, static_cast<int32_t>(3 * f + k)))
        points.push_back({{3 * (a.x + b.x), 3 * (a.y + b.y)}, chart});
    }
    if (orientation(q[0], q[1], q[2]) != 0)
      points.push_back({{2 * (q[0].x + q[1].x + q[2].x), 2 * (q[0].y + q[1].y + q[2].y)}, chart});
  }
  return points;
}

Box triangleBox(const GridPoint* q) {
  const auto [minX, maxX] = std::minmax({q[0].x, q[1].x, q[2].x});
  const auto [minY, maxY] = std::minmax({q[0].y, q[1].y, q[2].y});
  return {static_cast<double>(minX), static_cast<double>(minY), static_cast<double>(maxX), static_cast<double>(maxY)};
}

}  // namespace

std::vector<uint64_t> containedPointPairs(const UvCharts& charts, const WeldedCharts& welded) {
  std::vector<int32_t> faces;  // finite faces of non-zero area: only those can hold a point strictly
  for (size_t f = 0; f < charts.chartOfFace.size(); ++f) {
    const GridPoint* q = &charts.corner[3 * f];
    if (charts.chartOfFace[f] >= 0 && orientation(q[0], q[1], q[2]) != 0) faces.push_back(static_cast<int32_t>(f));
  }
  std::vector<uint64_t> pairs;
  if (faces.empty()) return pairs;
  auto boxOfFace = [&](int64_t i) { return triangleBox(&charts.corner[3 * static_cast<size_t>(faces[i])]); };
  Box bounds = boxOfFace(0);
  for (size_t i = 1; i < faces.size(); ++i) {
    const Box b = boxOfFace(static_cast<int64_t>(i));
    bounds = {std::min(bounds.minX, b.minX), std::min(bounds.minY, b.minY), std::max(bounds.maxX, b.maxX),
              std::max(bounds.maxY, b.maxY)};
  }
  const double area = std::max(bounds.maxX - bounds.minX, 1.0) * std::max(bounds.maxY - bounds.minY, 1.0);
  const BucketGrid grid(bounds, std::max(std::sqrt(area / static_cast<double>(faces.size())), 1.0),
                        static_cast<int64_t>(faces.size()), boxOfFace);
  for (const ChartPoint& point : chartPoints(charts, welded)) {
    // The grid is in unscaled grid units; the point is scaled.
    const int64_t cell = grid.cellOf(static_cast<double>(point.p.x) / kScale, static_cast<double>(point.p.y) / kScale);
    for (const int32_t* i = grid.begin(cell); i != grid.end(cell); ++i) {
      const size_t f = static_cast<size_t>(faces[*i]);
      if (charts.chartOfFace[f] == point.chart) continue;
      const GridPoint* q = &charts.corner[3 * f];
      if (strictlyInside(point.p, q[0] * kScale, q[1] * kScale, q[2] * kScale))
        pairs.push_back(chartPairKey(point.chart, charts.chartOfFace[f]));
    }
  }
  return pairs;
}

}  // namespace straightest::atlas_detail
