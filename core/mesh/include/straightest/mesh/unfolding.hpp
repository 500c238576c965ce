// unfolding.hpp (private) — a face laid flat in the frame of one of its halfedges: the halfedge's tail at
// (0, 0), its head at (length, 0), the face's third corner above the x axis. Window propagation and its
// back-trace move points from frame to frame with these, using edge lengths only (intrinsic geometry).
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::unfolding {

/// |v| by a square root: std::hypot (Vec2's norm) guards against overflow that lengths of a validated mesh
/// (coordinates below 1e50) cannot reach, at several times the cost, in the propagation's inner loop.
inline double length(const Vec2& v) { return std::sqrt(v.x * v.x + v.y * v.y); }

/// Length of every halfedge (3 per face, a face's halfedges in order).
inline std::vector<double> halfedgeLengths(const TriMesh& mesh) {
  std::vector<double> len(3 * static_cast<size_t>(mesh.numFaces()));
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h)
    len[h] = norm(mesh.position(mesh.head(h)) - mesh.position(mesh.tail(h)));
  return len;
}

/// The point at distance `toTail` from (0, 0) and `toHead` from (length, 0), above the x axis (below when
/// `below`). Rounding that makes the triangle inequality fail puts it on the axis.
inline Vec2 corner(double length, double toTail, double toHead, bool below = false) {
  const double x = (length * length + toTail * toTail - toHead * toHead) / (2 * length);
  const double y = std::sqrt(std::max(0.0, toTail * toTail - x * x));
  return {x, below ? -y : y};
}

/// face(h)'s third corner in h's frame.
inline Vec2 oppositeCorner(const std::vector<double>& len, int32_t h) {
  return corner(len[h], len[TriMesh::prev(h)], len[TriMesh::next(h)]);
}

/// q in the frame whose origin is `from` and whose x axis points to `to` (y: to the left of that axis).
inline Vec2 toFrame(const Vec2& q, const Vec2& from, const Vec2& to) {
  const Vec2 axis = to - from;
  const double l = length(axis);
  const Vec2 u = axis / l, d = q - from;
  return {dot(d, u), cross(u, d)};
}

/// The parameter (0 = a, 1 = b) where the line from `from` through `through` meets segment a–b, clamped
/// to [0, 1]; `parallel` when the line runs along the segment.
inline double lineMeetsSegment(const Vec2& from, const Vec2& through, const Vec2& a, const Vec2& b, double parallel) {
  const Vec2 d = through - from;
  const double den = cross(d, b - a);
  if (std::fabs(den) <= 1e-300) return parallel;
  const double t = cross(d, from - a) / den;
  return std::clamp(t, 0.0, 1.0);
}

}  // namespace straightest::unfolding
