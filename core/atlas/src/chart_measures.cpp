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

/// Chart indices by decreasing key (ties in input order).
std::vector<int32_t> orderedBy(const std::vector<double>& key) {
  std::vector<int32_t> order(key.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return key[a] > key[b]; });
  return order;
}

}  // namespace

ChartMeasures measureCharts(const std::vector<ChartShape>& charts, bool rotate, const AtlasFrame& frame) {
  ChartMeasures measures;
  const Vec2 usable{static_cast<double>(frame.width - 2 * frame.border),
                    static_cast<double>(frame.height - 2 * frame.border)};
  std::vector<double> rectangleArea(charts.size()), longestSide(charts.size()), chartAreas(charts.size());
  measures.scaleUpperBound = kInfinity;
  for (size_t i = 0; i < charts.size(); ++i) {
    const double base = rotate ? minAreaRectangleAngle(charts[i].triangles) : 0;
    std::vector<double> angles{0};
    if (rotate) {
      angles.clear();
      for (int k = 0; k < 4; ++k) angles.push_back(base + k * kPi / 2);
    }
    measures.angles.push_back(angles);
    const Vec2 extent = rotatedExtent(charts[i].triangles, base);
    rectangleArea[i] = extent.x * extent.y;
    longestSide[i] = std::max(extent.x, extent.y);
    measures.largestExtent = std::max({measures.largestExtent, extent.x, extent.y});
    measures.scaleUpperBound = std::min(measures.scaleUpperBound, scaleThatFits(extent, usable, rotate));
    chartAreas[i] = chartArea(charts[i].triangles);
    measures.totalArea += chartAreas[i];
  }
  measures.fillScale = measures.totalArea > 0 ? std::sqrt(usable.x * usable.y / measures.totalArea) : kInfinity;
  measures.scaleUpperBound = std::min(measures.scaleUpperBound, measures.fillScale);
  measures.orders = {orderedBy(rectangleArea), orderedBy(longestSide), orderedBy(chartAreas)};
  return measures;
}

}  // namespace straightest::atlas_detail
