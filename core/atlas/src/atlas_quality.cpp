// atlas_quality.cpp — measureAtlas: charts from the uv, then their topology, stretch, overlaps and gaps.
#include "straightest/atlas/atlas_quality.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "chart_boundaries.hpp"
#include "chart_containment.hpp"
#include "chart_stretch.hpp"
#include "chart_topology.hpp"
#include "uv_charts.hpp"

namespace straightest {

namespace {

using namespace atlas_detail;

void countCorners(const std::vector<Vec2>& cornerUv, AtlasQuality& q) {
  for (const Vec2& uv : cornerUv) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) ++q.nonFinite;
    else if (uv.x < 0 || uv.x > 1 || uv.y < 0 || uv.y > 1) ++q.outside;
  }
}

/// The first search radius for gaps: the padding, and at least a few mean boundary edges (so the gap
/// between packed charts is usually found in one pass).
double firstGapRadius(const std::vector<BoundarySegment>& segments, double padding) {
  double length = 0;
  for (const BoundarySegment& s : segments) length += norm(s.tb - s.ta);
  return std::max({padding, 4 * length / std::max<size_t>(segments.size(), 1), 1.0});
}

/// Smallest distance between two different charts, searching ever wider when none is closer than the radius.
double widerMinGap(const std::vector<BoundarySegment>& segments, int32_t charts, double radius) {
  double extent = 0;
  for (const BoundarySegment& s : segments) extent = std::max({extent, std::abs(s.ta.x), std::abs(s.ta.y)});
  for (;;) {
    radius *= 4;
    const BoundaryPairs wide = nearBoundaryPairs(segments, charts, radius, false);
    double gap = std::numeric_limits<double>::infinity();
    for (const auto& [key, d] : wide.closer) gap = std::min(gap, d);
    if (gap < radius || radius > 4 * extent) return gap;
  }
}

/// The first face of every chart in an overlapping pair or crossing itself, ascending.
std::vector<int32_t> firstFaces(const UvCharts& charts, const std::vector<uint64_t>& pairs,
                                const std::vector<uint8_t>& selfCrossing) {
  std::vector<uint8_t> bad(selfCrossing);
  for (uint64_t key : pairs) bad[key >> 32] = bad[static_cast<uint32_t>(key)] = 1;
  std::vector<int32_t> faces;
  for (int32_t f = 0; f < static_cast<int32_t>(charts.chartOfFace.size()); ++f) {
    const int32_t c = charts.chartOfFace[f];
    if (c >= 0 && bad[c]) faces.push_back(f), bad[c] = 0;
  }
  return faces;
}

/// Overlapping chart pairs and self-crossing charts, minimum gap and padding violations.
void measureOverlapsAndGaps(const TriMesh& mesh, const UvCharts& charts, const WeldedCharts& welded,
                            const QualityOptions& options, AtlasQuality& q) {
  const auto segments = chartBoundarySegments(mesh, charts, options.width, options.height);
  const double radius = firstGapRadius(segments, options.padding);
  BoundaryPairs near = nearBoundaryPairs(segments, charts.charts, radius, true);
  std::vector<uint64_t> overlapping = std::move(near.crossingPairs);
  const std::vector<uint64_t> contained = containedPointPairs(charts, welded);
  overlapping.insert(overlapping.end(), contained.begin(), contained.end());
  std::sort(overlapping.begin(), overlapping.end());
  overlapping.erase(std::unique(overlapping.begin(), overlapping.end()), overlapping.end());
  q.overlaps = static_cast<int64_t>(overlapping.size()) +
               std::count(near.selfCrossing.begin(), near.selfCrossing.end(), uint8_t{1});
  q.overlappingFaces = firstFaces(charts, overlapping, near.selfCrossing);
  for (uint64_t key : overlapping) near.closer[key] = 0;
  // Distances are measured between snapped points, each up to half a grid step (2^-25 of the uv square) per
  // coordinate from the uv given: a gap within that of the padding cannot be told from it.
  const double snapSlack = std::sqrt(2.0) / kGridUnitsPerUv * std::max(options.width, options.height);
  double gap = std::numeric_limits<double>::infinity();
  for (const auto& [key, d] : near.closer) {
    gap = std::min(gap, d);
    q.paddingViolations += d < options.padding - snapSlack;
  }
  q.minGapTexels = gap < radius || charts.charts < 2 ? gap : widerMinGap(segments, charts.charts, radius);
}

}  // namespace

AtlasQuality measureAtlas(const TriMesh& mesh, const std::vector<Vec2>& cornerUv, const QualityOptions& options) {
  if (cornerUv.size() != 3 * static_cast<size_t>(mesh.numFaces()))
    throw std::invalid_argument("measureAtlas: cornerUv needs 3 uv per face");
  if (options.width <= 0 || options.height <= 0)
    throw std::invalid_argument("measureAtlas: width and height must be positive");
  AtlasQuality q;
  countCorners(cornerUv, q);
  const UvCharts charts = findUvCharts(mesh, cornerUv);
  q.charts = charts.charts;
  q.seamEdges = charts.seamEdges;
  q.seamLength = charts.seamLength;
  const WeldedCharts welded = weldCharts(mesh, charts);
  q.nonDiskCharts = static_cast<int32_t>(std::count(welded.isDisk.begin(), welded.isDisk.end(), uint8_t{0}));
  ChartStretch stretch = measureChartStretch(mesh, cornerUv, charts,
                                             Vec2{static_cast<double>(options.width),
                                                  static_cast<double>(options.height)});
  q.l2 = stretch.l2, q.linf = stretch.linf;
  q.chartL2 = std::move(stretch.chartL2), q.chartLinf = std::move(stretch.chartLinf);
  q.flipped = stretch.flipped, q.mirroredCharts = stretch.mirroredCharts, q.degenerate = stretch.degenerate;
  q.utilization = stretch.uvArea;
  measureOverlapsAndGaps(mesh, charts, welded, options, q);
  return q;
}

}  // namespace straightest
