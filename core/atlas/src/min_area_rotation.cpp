// min_area_rotation.cpp — convex hull and the rotating-calipers search for the minimum-area rectangle.
#include "min_area_rotation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace straightest::atlas_detail {

std::vector<Vec2> convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  size_t count = 0;
  auto turnsLeft = [&](Vec2 p) { return cross(hull[count - 1] - hull[count - 2], p - hull[count - 2]) > 0; };
  for (const Vec2& p : points) {  // lower hull
    while (count >= 2 && !turnsLeft(p)) --count;
    hull[count++] = p;
  }
  const size_t lowerCount = count + 1;
  for (size_t i = points.size() - 1; i-- > 0;) {  // upper hull
    while (count >= lowerCount && !turnsLeft(points[i])) --count;
    hull[count++] = points[i];
  }
  hull.resize(count - 1);  // the last point repeats the first
  return hull;
}

double minAreaRectangleAngle(const std::vector<Vec2>& points) {
  const std::vector<Vec2> hull = convexHull(points);
  if (hull.size() < 2) return 0;
  double bestArea = std::numeric_limits<double>::infinity(), bestAngle = 0;
  // Every hull edge as the rectangle's base; the hulls of charts are small enough that projecting the whole
  // hull per edge (quadratic) costs less than keeping four calipers in step.
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2 edge = hull[(i + 1) % hull.size()] - hull[i];
    const double length = norm(edge);
    if (length == 0) continue;
    const Vec2 along = edge / length, across{-along.y, along.x};
    double minAlong = 0, maxAlong = 0, maxAcross = 0, minAcross = 0;
    for (const Vec2& p : hull) {
      const Vec2 d = p - hull[i];
      minAlong = std::min(minAlong, dot(d, along));
      maxAlong = std::max(maxAlong, dot(d, along));
      minAcross = std::min(minAcross, dot(d, across));
      maxAcross = std::max(maxAcross, dot(d, across));
    }
    const double area = (maxAlong - minAlong) * (maxAcross - minAcross);
    if (area < bestArea) {
      bestArea = area;
      bestAngle = -std::atan2(edge.y, edge.x);
    }
  }
  return bestAngle;
}

}  // namespace straightest::atlas_detail
