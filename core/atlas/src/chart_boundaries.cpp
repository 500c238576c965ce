// chart_boundaries.cpp — candidate segment pairs from a bucket grid of boxes grown by half the radius; each
// pair is examined in one cell only (the one holding the low corner of the grown boxes' overlap).
#include "chart_boundaries.hpp"

#include <algorithm>
#include <cmath>

#include "bucket_grid.hpp"

namespace straightest::atlas_detail {

namespace {

Vec2 toTexels(const GridPoint& p, int32_t width, int32_t height) {
  return {static_cast<double>(p.x) / kGridUnitsPerUv * width, static_cast<double>(p.y) / kGridUnitsPerUv * height};
}

Box boxOf(const BoundarySegment& s) {
  return {std::min(s.ta.x, s.tb.x), std::min(s.ta.y, s.tb.y), std::max(s.ta.x, s.tb.x), std::max(s.ta.y, s.tb.y)};
}

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + ab * t));
}

/// Distance in texels between two segments: 0 when they meet (exactly, on the snapped points).
double segmentDistance(const BoundarySegment& s, const BoundarySegment& t) {
  if (intersect(s.a, s.b, t.a, t.b)) return 0;
  return std::min(std::min(pointSegmentDistance(s.ta, t.ta, t.tb), pointSegmentDistance(s.tb, t.ta, t.tb)),
                  std::min(pointSegmentDistance(t.ta, s.ta, s.tb), pointSegmentDistance(t.tb, s.ta, s.tb)));
}

/// A cell side giving about one cell per segment over the segments' bounds, and no less than the radius.
double cellSide(const Box& bounds, size_t segments, double radius) {
  const double area = std::max(bounds.maxX - bounds.minX, 1e-9) * std::max(bounds.maxY - bounds.minY, 1e-9);
  return std::max(std::sqrt(area / std::max<size_t>(segments, 1)), radius);
}

/// Examines one candidate pair: crossings (same chart or not), and the distance between different charts.
void examinePair(const BoundarySegment& s, const BoundarySegment& t, double radius, bool findCrossings,
                 BoundaryPairs& out) {
  if (findCrossings && properlyCross(s.a, s.b, t.a, t.b)) {
    if (s.chart == t.chart) out.selfCrossing[s.chart] = 1;
    else out.crossingPairs.push_back(chartPairKey(s.chart, t.chart));
  }
  if (s.chart == t.chart) return;
  const double d = segmentDistance(s, t);
  if (d >= radius) return;
  auto [it, added] = out.closer.emplace(chartPairKey(s.chart, t.chart), d);
  if (!added) it->second = std::min(it->second, d);
}

}  // namespace

std::vector<BoundarySegment> chartBoundarySegments(const TriMesh& mesh, const UvCharts& charts, int32_t width,
                                                   int32_t height) {
  std::vector<BoundarySegment> segments;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int32_t chart = charts.chartOfFace[TriMesh::face(h)];
    if (chart < 0 || !isChartBoundary(charts, h)) continue;
    const GridPoint &a = charts.corner[h], &b = charts.corner[TriMesh::next(h)];
    segments.push_back({a, b, toTexels(a, width, height), toTexels(b, width, height), chart});
  }
  return segments;
}

BoundaryPairs nearBoundaryPairs(const std::vector<BoundarySegment>& segments, int32_t charts, double radius,
                                bool findCrossings) {
  BoundaryPairs out;
  out.selfCrossing.assign(charts, 0);
  if (segments.empty()) return out;
  const double grow = radius / 2;
  auto grown = [&](int64_t i) { return boxOf(segments[i]).expanded(grow); };
  Box bounds = grown(0);
  for (size_t i = 1; i < segments.size(); ++i) {
    const Box b = grown(static_cast<int64_t>(i));
    bounds = {std::min(bounds.minX, b.minX), std::min(bounds.minY, b.minY), std::max(bounds.maxX, b.maxX),
              std::max(bounds.maxY, b.maxY)};
  }
  const BucketGrid grid(bounds, cellSide(bounds, segments.size(), radius), static_cast<int64_t>(segments.size()),
                        grown);
  for (int64_t cell = 0; cell < grid.cellCount(); ++cell) {
    for (const int32_t* i = grid.begin(cell); i != grid.end(cell); ++i) {
      const Box bi = grown(*i);
      for (const int32_t* j = i + 1; j != grid.end(cell); ++j) {
        const Box bj = grown(*j);
        if (!bi.meets(bj) || grid.cellOf(std::max(bi.minX, bj.minX), std::max(bi.minY, bj.minY)) != cell) continue;
        examinePair(segments[*i], segments[*j], radius, findCrossings, out);
      }
    }
  }
  return out;
}

}  // namespace straightest::atlas_detail
