// chart_shape.cpp — a chart's hull fill, from its uv corners' convex hull.
#include "chart_shape.hpp"

#include <algorithm>
#include <cmath>

#include "min_area_rotation.hpp"

namespace straightest::atlas {

double hullFill(const std::vector<Vec2>& cornerUv) {
  double twiceArea = 0;
  for (size_t i = 0; i + 2 < cornerUv.size(); i += 3)
    twiceArea += cross(cornerUv[i + 1] - cornerUv[i], cornerUv[i + 2] - cornerUv[i]);
  const std::vector<Vec2> hull = atlas_detail::convexHull(cornerUv);
  double twiceHullArea = 0;
  for (size_t i = 0; i < hull.size(); ++i) twiceHullArea += cross(hull[i], hull[(i + 1) % hull.size()]);
  return twiceHullArea > 0 ? std::min(1.0, std::fabs(twiceArea) / twiceHullArea) : 1;
}

}  // namespace straightest::atlas
