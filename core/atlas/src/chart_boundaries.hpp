// chart_boundaries.hpp — pairs of chart boundary edges near each other: exact crossings (between charts and
// of a chart with itself) and the distance in texels between every two charts closer than a radius.
#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "uv_charts.hpp"

namespace straightest::atlas_detail {

/// A chart's boundary edge: its snapped endpoints, the same in texels, and its chart.
struct BoundarySegment {
  GridPoint a, b;
  Vec2 ta, tb;
  int32_t chart;
};

/// Chart pair (smaller id first) as one key.
inline uint64_t chartPairKey(int32_t a, int32_t b) {
  if (a > b) std::swap(a, b);
  return static_cast<uint64_t>(a) << 32 | static_cast<uint32_t>(b);
}

struct BoundaryPairs {
  std::vector<uint64_t> crossingPairs;          // chart pairs whose boundaries properly cross (may repeat)
  std::vector<uint8_t> selfCrossing;            // per chart: its boundary properly crosses itself
  std::unordered_map<uint64_t, double> closer;  // chart pairs at distance < radius: their distance in texels
};

/// The boundary edges of every chart, with texel coordinates at width × height.
std::vector<BoundarySegment> chartBoundarySegments(const TriMesh& mesh, const UvCharts& charts, int32_t width,
                                                   int32_t height);

/// Every pair of segments within `radius` texels, found through a bucket grid; crossings only when asked.
BoundaryPairs nearBoundaryPairs(const std::vector<BoundarySegment>& segments, int32_t charts, double radius,
                                bool findCrossings);

}  // namespace straightest::atlas_detail
