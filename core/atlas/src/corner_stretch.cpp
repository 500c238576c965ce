// chart_stretch.cpp — per-face stretch from the Jacobian of the uv → 3D map, summed over 3D area.
#include "corner_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "straightest/param/texture_stretch.hpp"

namespace straightest::atlas {

namespace {
/// The squared L2 stretch and the L∞ stretch of one face (3D area > 0, uv area > 0).
std::pair<double, double> faceStretch(const TriMesh& mesh, int32_t f, const Vec2* q) {
  const Triangle& t = mesh.triangle(f);
  const Vec3 &p1 = mesh.position(t[0]), &p2 = mesh.position(t[1]), &p3 = mesh.position(t[2]);
  const double A = cross(q[1] - q[0], q[2] - q[0]);
  const Vec3 Ss = (p1 * (q[1].y - q[2].y) + p2 * (q[2].y - q[0].y) + p3 * (q[0].y - q[1].y)) / A;
  const Vec3 St = (p1 * (q[2].x - q[1].x) + p2 * (q[0].x - q[2].x) + p3 * (q[1].x - q[0].x)) / A;
  const double a = dot(Ss, Ss), b = dot(Ss, St), c = dot(St, St);
  const double root = std::sqrt((a - c) * (a - c) + 4 * b * b);
  return {(a + c) / 2, std::sqrt(((a + c) + root) / 2)};
}
}  // namespace

CornerStretch cornerStretch(const TriMesh& mesh, const std::vector<int32_t>& faces, const std::vector<Vec2>& cornerUv) {
  CornerStretch s;
  double sumA2 = 0, sumA3 = 0, sumL2 = 0, maxLinf = 0;
  for (size_t i = 0; i < faces.size(); ++i) {
    sumA2 += std::fabs(twiceUvArea(cornerUv, i)) / 2;
    sumA3 += mesh.faceArea(faces[i]);
  }
  const double threshold = kDegenerateUV * sumA2 / std::max<size_t>(1, faces.size());
  for (size_t i = 0; i < faces.size(); ++i) {
    const double a2 = twiceUvArea(cornerUv, i) / 2;
    if (!(a2 > threshold)) {
      ++s.flipped;
      continue;
    }
    const double a3 = mesh.faceArea(faces[i]);
    if (!(a3 > 0)) continue;  // a zero-area 3D face stretches nothing
    const auto [l2Squared, linf] = faceStretch(mesh, faces[i], &cornerUv[3 * i]);
    sumL2 += l2Squared * a3;
    maxLinf = std::max(maxLinf, linf);
  }
  if (s.flipped > 0 || !(sumA3 > 0)) {
    if (s.flipped > 0) s.l2 = s.linf = std::numeric_limits<double>::infinity();
    return s;
  }
  const double scale = std::sqrt(sumA2 / sumA3);
  s.l2 = std::sqrt(sumL2 / sumA3) * scale;
  s.linf = maxLinf * scale;
  return s;
}

}  // namespace straightest::atlas
