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
// Each chart is tried at 16 turns from its minimum rectangle's angle (the right angles among them): a long
// chart may only fit along the diagonal, and an odd one nests into its neighbours' outlines at a turn
// between the right angles; fewer turns for the small charts pack less (docs/BENCHMARKS.md).
constexpr int kTurns = 16;

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

/// The largest scale at which a chart of these sides fits the usable rectangle.
double scaleThatFits(Vec2 extent, Vec2 usable) {
  auto fit = [](double side, double room) { return side > 0 ? room / side : kInfinity; };
  return std::min(fit(extent.x, usable.x), fit(extent.y, usable.y));
}

/// `turns` rotations evenly spread over the full turn from `base` (4: the right angles).
std::vector<double> turnsOf(double base, int turns) {
  std::vector<double> angles;
  for (int k = 0; k < turns; ++k) angles.push_back(base + k * 2 * kPi / turns);
  return angles;
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
  const size_t count = charts.size();
  std::vector<double> baseAngle(count, 0), rectangleArea(count), longestSide(count), chartAreas(count);
  for (size_t i = 0; i < count; ++i) {
    baseAngle[i] = rotate ? minAreaRectangleAngle(charts[i].triangles) : 0;
    const Vec2 extent = rotatedExtent(charts[i].triangles, baseAngle[i]);
    rectangleArea[i] = extent.x * extent.y;
    longestSide[i] = std::max(extent.x, extent.y);
    measures.largestExtent = std::max(measures.largestExtent, longestSide[i]);
    chartAreas[i] = chartArea(charts[i].triangles);
    measures.totalArea += chartAreas[i];
  }
  measures.fillScale = measures.totalArea > 0 ? std::sqrt(usable.x * usable.y / measures.totalArea) : kInfinity;
  measures.scaleUpperBound = measures.fillScale;
  for (size_t i = 0; i < count; ++i) {
    measures.angles.push_back(rotate ? turnsOf(baseAngle[i], kTurns) : std::vector<double>{0});
    measures.beyondRightAngles = measures.beyondRightAngles || measures.angles.back().size() > 4;
    double fits = 0;
    for (const double angle : measures.angles.back())
      fits = std::max(fits, scaleThatFits(rotatedExtent(charts[i].triangles, angle), usable));
    measures.scaleUpperBound = std::min(measures.scaleUpperBound, fits);
  }
  measures.orders = {orderedBy(rectangleArea), orderedBy(longestSide), orderedBy(chartAreas)};
  return measures;
}

}  // namespace straightest::atlas_detail
