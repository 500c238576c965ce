// Polygon triangulation by ear clipping in the polygon's Newell plane (see polygon_triangulation.hpp).
// The Newell normal is the polygon's area vector, so in the frame (u, w) with u × w = normal the
// polygon winds counter-clockwise whatever its shape: a convex corner is a left turn there.
#include "straightest/mesh/polygon_triangulation.hpp"

#include <numeric>

namespace straightest {

void triangulatePolygon(const std::vector<Vec3>& positions, const std::vector<int32_t>& polygon,
                        std::vector<Triangle>& out) {
  const size_t n = polygon.size();
  auto fan = [&](const std::vector<int32_t>& ring) {
    for (size_t i = 1; i + 1 < ring.size(); ++i) out.push_back({ring[0], ring[i], ring[i + 1]});
  };
  if (n < 3) return;
  // Ear clipping is quadratic; very large polygons (never seen in practice) take the fan.
  if (n == 3 || n > 256) {
    fan(polygon);
    return;
  }
  Vec3 normal;
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = positions[polygon[i]];
    const Vec3& b = positions[polygon[(i + 1) % n]];
    normal += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  normal = normalized(normal);
  if (squaredNorm(normal) == 0) {
    fan(polygon);
    return;
  }
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(normal, helper)), w = cross(normal, u);
  std::vector<Vec2> p;
  p.reserve(n);
  for (int32_t v : polygon) p.push_back({dot(positions[v], u), dot(positions[v], w)});
  auto leftTurn = [&](size_t a, size_t b, size_t c) { return cross(p[b] - p[a], p[c] - p[a]); };

  std::vector<size_t> corners(n);  // the corners not clipped yet, in order around the polygon
  std::iota(corners.begin(), corners.end(), 0);
  while (corners.size() > 3) {
    bool clipped = false;
    const size_t m = corners.size();
    for (size_t i = 0; i < m && !clipped; ++i) {
      const size_t a = corners[(i + m - 1) % m], b = corners[i], c = corners[(i + 1) % m];
      if (leftTurn(a, b, c) <= 0) continue;  // reflex or flat corner: not an ear
      bool empty = true;                     // no other corner inside (or on) the ear
      for (size_t j = 0; j < m && empty; ++j) {
        const size_t q = corners[j];
        if (q == a || q == b || q == c) continue;
        if (leftTurn(a, b, q) >= 0 && leftTurn(b, c, q) >= 0 && leftTurn(c, a, q) >= 0) empty = false;
      }
      if (!empty) continue;
      out.push_back({polygon[a], polygon[b], polygon[c]});
      corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;  // no ear left (a degenerate or self-intersecting outline): fan the rest
  }
  std::vector<int32_t> rest;
  for (size_t i : corners) rest.push_back(polygon[i]);
  fan(rest);
}

}  // namespace straightest
