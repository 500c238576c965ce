// chart_measures.cpp — rotations, areas, order and the scale's upper bound (every chart inside the usable
// square, and the total area at most the usable area).
#include "chart_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "chart_raster.hpp"
#include "min_area_rotation.hpp"

namespace straightest::atlas_detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double chartArea(const std::vector<Vec2>& triangles) {
  double area = 0;
  for (size_t t = 0; t + 2 < triangles.size(); t += 3)
    area += std::abs(cross(triangles[t + 1] - triangles[t], triangles[t + 2] - triangles[t])) / 2;
  return area;
}

/// The chart's bounding box sides after the rotation `angle`.
Vec2 rotatedExtent(const std::vector<Vec2>& triangles, double angle) {
  Vec2 lo{kInfinity, kInfinity}, hi = -lo;
  for (const Vec2& uv : triangles) {
    const Vec2 p = rotatedAndScaled(uv, 1, angle);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  return hi - lo;
}

/// The largest scale at which a chart of these sides fits the usable rectangle, either way round when rotating.
double scaleThatFits(Vec2 extent, Vec2 usable, bool rotate) {
  auto fit = [](double side, double room) { return side > 0 ? room / side : kInfinity; };
  const double upright = std::min(fit(extent.x, usable.x), fit(extent.y, usable.y));
  const double turned = std::min(fit(extent.y, usable.x), fit(extent.x, usable.y));
  return rotate ? std::max(upright, turned) : upright;
}

}  // namespace

ChartMeasures measureCharts(const std::vector<ChartShape>& charts, bool rotate, const AtlasFrame& frame) {
  ChartMeasures measures;
  const Vec2 usable{static_cast<double>(frame.width - 2 * frame.border),
                    static_cast<double>(frame.height - 2 * frame.border)};
  std::vector<double> rectangleArea(charts.size());
  measures.scaleUpperBound = kInfinity;
  for (size_t i = 0; i < charts.size(); ++i) {
    const double base = rotate ? minAreaRectangleAngle(charts[i].triangles) : 0;
    measures.angles.push_back(rotate ? std::vector<double>{base, base + kPi / 2, base + kPi, base + 3 * kPi / 2}
                                     : std::vector<double>{0});
    const Vec2 extent = rotatedExtent(charts[i].triangles, base);
    rectangleArea[i] = extent.x * extent.y;
    measures.largestExtent = std::max({measures.largestExtent, extent.x, extent.y});
    measures.scaleUpperBound = std::min(measures.scaleUpperBound, scaleThatFits(extent, usable, rotate));
    measures.totalArea += chartArea(charts[i].triangles);
  }
  if (measures.totalArea > 0)
    measures.scaleUpperBound = std::min(measures.scaleUpperBound, std::sqrt(usable.x * usable.y / measures.totalArea));
  measures.order.resize(charts.size());
  std::iota(measures.order.begin(), measures.order.end(), 0);
  std::stable_sort(measures.order.begin(), measures.order.end(),
                   [&](int32_t a, int32_t b) { return rectangleArea[a] > rectangleArea[b]; });
  return measures;
}

}  // namespace straightest::atlas_detail
