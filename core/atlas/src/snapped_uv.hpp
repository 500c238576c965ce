// snapped_uv.hpp — uv snapped to the integer grid of 2^-24, and exact orientation predicates on it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "straightest/base/vec3.hpp"

namespace straightest::atlas_detail {

__extension__ typedef __int128 Int128;  // products of 41-bit differences need 82 bits

inline constexpr double kGridUnitsPerUv = 16777216.0;  // 2^24
inline constexpr double kClampUv = 32768.0;            // 2^15: keeps coordinates within 2^39

/// A snapped uv: integer multiples of 2^-24 (scaled by 3 where centroids are compared).
struct GridPoint {
  int64_t x = 0, y = 0;
  bool operator==(const GridPoint& o) const { return x == o.x && y == o.y; }
  bool operator!=(const GridPoint& o) const { return !(*this == o); }
  GridPoint operator*(int64_t k) const { return {x * k, y * k}; }
};

/// The nearest grid point of a finite uv (coordinates clamped to ±2^15 so products never overflow).
inline GridPoint snap(const Vec2& uv) {
  auto coordinate = [](double u) {
    return static_cast<int64_t>(std::llround(std::clamp(u, -kClampUv, kClampUv) * kGridUnitsPerUv));
  };
  return {coordinate(uv.x), coordinate(uv.y)};
}

/// +1 when a, b, c turn counter-clockwise, −1 clockwise, 0 collinear (exact).
inline int orientation(const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  const Int128 det = static_cast<Int128>(b.x - a.x) * (c.y - a.y) - static_cast<Int128>(b.y - a.y) * (c.x - a.x);
  return (det > 0) - (det < 0);
}

/// The sign of the double-precision area of uv triangle abc when it exceeds the cross product's rounding
/// error (a bound a little above Shewchuk's for the orientation determinant), else 0.
inline int8_t certainSign(Vec2 a, Vec2 b, Vec2 c) {
  const double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double bound = 1e-15 * (std::fabs(left) + std::fabs(right));
  return det > bound ? 1 : det < -bound ? -1 : 0;
}

/// Segments ab and cd cross at one point interior to both (touching or collinear overlap is no crossing).
inline bool properlyCross(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  return o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0 && o1 != o2 && o3 != o4;
}

/// p lies on segment ab, given that a, b, p are collinear.
inline bool withinBox(const GridPoint& a, const GridPoint& b, const GridPoint& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Segments ab and cd share at least one point (closed segments, exact).
inline bool intersect(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && withinBox(a, b, c)) || (o2 == 0 && withinBox(a, b, d)) || (o3 == 0 && withinBox(c, d, a)) ||
         (o4 == 0 && withinBox(c, d, b));
}

/// p is strictly inside triangle abc of either winding (not on its edges; never inside a degenerate one).
inline bool strictlyInside(const GridPoint& p, const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  const int o1 = orientation(a, b, p), o2 = orientation(b, c, p), o3 = orientation(c, a, p);
  return o1 != 0 && o1 == o2 && o2 == o3;
}

}  // namespace straightest::atlas_detail
