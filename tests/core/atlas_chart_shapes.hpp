// atlas_chart_shapes.hpp — synthetic chart sets for the packer's tests and benchmark: random convex polygons,
// L shapes and long strips (counter-clockwise triangles, in units), reproducible from a seed.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "straightest/atlas/chart_packing.hpp"

namespace straightest::testing {

/// A fan of triangles over a convex polygon given counter-clockwise.
inline ChartShape fanChart(const std::vector<Vec2>& polygon) {
  ChartShape chart;
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    chart.triangles.insert(chart.triangles.end(), {polygon[0], polygon[i], polygon[i + 1]});
  return chart;
}

/// A convex polygon of 5–12 vertices on an ellipse of radii (a, b), rotated and shifted at random.
inline ChartShape randomConvexChart(std::mt19937& random, double size) {
  std::uniform_real_distribution<double> unit(0, 1);
  const int count = 5 + static_cast<int>(unit(random) * 8);
  const double a = size * (0.5 + unit(random)), b = size * (0.3 + 0.7 * unit(random)), turn = 6.283 * unit(random);
  std::vector<Vec2> polygon;
  for (int i = 0; i < count; ++i) {
    const double t = 6.283185307179586 * (i + 0.8 * unit(random)) / count;
    const Vec2 p{a * std::cos(t), b * std::sin(t)};
    polygon.push_back(
        Vec2{p.x * std::cos(turn) - p.y * std::sin(turn) + 3, p.x * std::sin(turn) + p.y * std::cos(turn) - 7});
  }
  return fanChart(polygon);
}

/// An L of arm length `size` and arm width size × (0.2..0.5), made of two rectangles (four triangles).
inline ChartShape lShapedChart(std::mt19937& random, double size) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double w = size * (0.2 + 0.3 * unit(random)), l = size * (0.8 + 0.6 * unit(random));
  ChartShape chart = fanChart({{0, 0}, {l, 0}, {l, w}, {0, w}});
  const ChartShape arm = fanChart({{0, w}, {w, w}, {w, l}, {0, l}});
  chart.triangles.insert(chart.triangles.end(), arm.triangles.begin(), arm.triangles.end());
  return chart;
}

/// A strip `size` × (2..4) long and size × 0.3 wide, bent along an arc, as a row of quads.
inline ChartShape stripChart(std::mt19937& random, double size) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double length = size * (2 + 2 * unit(random)), width = size * 0.3, bend = 0.3 * (unit(random) - 0.5);
  const int segments = 12;
  std::vector<Vec2> centre{{0, 0}}, normal;
  for (int i = 0; i <= segments; ++i) {
    const double angle = bend * i;
    normal.push_back({-std::sin(angle), std::cos(angle)});
    centre.push_back(centre.back() + Vec2{std::cos(angle), std::sin(angle)} * (length / segments));
  }
  ChartShape chart;
  for (int i = 0; i < segments; ++i) {
    const Vec2 a = centre[i], b = centre[i + 1], c = b + normal[i + 1] * width, d = a + normal[i] * width;
    chart.triangles.insert(chart.triangles.end(), {a, b, c, a, c, d});
  }
  return chart;
}

/// `count` charts: convex polygons, L shapes and strips in turn, sizes spread over a factor of ~4.
inline std::vector<ChartShape> mixedCharts(int count, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<ChartShape> charts;
  for (int i = 0; i < count; ++i) {
    const double size = 0.5 + 1.5 * unit(random) * unit(random);
    if (i % 3 == 0) charts.push_back(randomConvexChart(random, size));
    else if (i % 3 == 1) charts.push_back(lShapedChart(random, size));
    else charts.push_back(stripChart(random, size));
  }
  return charts;
}

}  // namespace straightest::testing
