// boundary_overlaps.cpp — does a map's boundary cross itself: segment crossings along a sweep in x.
#include "straightest/param/boundary_overlaps.hpp"

#include <algorithm>

namespace straightest {
namespace {

struct Segment {
  Vec2 a, b;
  int32_t va, vb;  // mesh vertices: segments sharing one are neighbours, not a crossing
  double minX, maxX;
};

/// Sign of the turn a → b → c (exact zero only for exactly collinear points).
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double t = cross(b - a, c - a);
  return (t > 0) - (t < 0);
}

/// c lies within the bounding box of a, b (used when the three are collinear).
bool withinBox(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

/// Closed segments p and q cross or touch.
bool intersect(const Segment& p, const Segment& q) {
  const int o1 = orientation(p.a, p.b, q.a), o2 = orientation(p.a, p.b, q.b);
  const int o3 = orientation(q.a, q.b, p.a), o4 = orientation(q.a, q.b, p.b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  return (o1 == 0 && withinBox(p.a, p.b, q.a)) || (o2 == 0 && withinBox(p.a, p.b, q.b)) ||
         (o3 == 0 && withinBox(q.a, q.b, p.a)) || (o4 == 0 && withinBox(q.a, q.b, p.b));
}

}  // namespace

int64_t boundaryOverlaps(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  std::vector<Segment> segments;
  for (const std::vector<int32_t>& loop : mesh.boundaryLoops())
    for (size_t i = 0; i < loop.size(); ++i) {
      const int32_t va = loop[i], vb = loop[(i + 1) % loop.size()];
      const Vec2 &a = uv[va], &b = uv[vb];
      segments.push_back({a, b, va, vb, std::min(a.x, b.x), std::max(a.x, b.x)});
    }
  // Sort and sweep on x: only segments whose x-ranges overlap are compared.
  std::sort(segments.begin(), segments.end(), [](const Segment& p, const Segment& q) { return p.minX < q.minX; });
  int64_t crossings = 0;
  for (size_t i = 0; i < segments.size(); ++i) {
    const Segment& p = segments[i];
    for (size_t j = i + 1; j < segments.size() && segments[j].minX <= p.maxX; ++j) {
      const Segment& q = segments[j];
      if (p.va == q.va || p.va == q.vb || p.vb == q.va || p.vb == q.vb) continue;
      // Two copies of one point (a pinch split into two vertices at the very same uv) are neighbours too.
      if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) continue;
      if (std::max(p.a.y, p.b.y) < std::min(q.a.y, q.b.y) || std::max(q.a.y, q.b.y) < std::min(p.a.y, p.b.y)) continue;
      if (intersect(p, q)) ++crossings;
    }
  }
  return crossings;
}

}  // namespace straightest
