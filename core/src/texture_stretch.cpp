#include "straightest/texture_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "straightest/boundary_overlaps.hpp"

namespace straightest {

StretchMetrics textureStretch(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  StretchMetrics m;
  const int32_t nf = mesh.numFaces();
  const double inf = std::numeric_limits<double>::infinity();
  m.faceStretch.assign(nf, 0.0f);
  std::vector<double> a2(nf);
  double meanAbsA2 = 0;
  for (int32_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangle(f);
    const Vec2 &q1 = uv[t[0]], &q2 = uv[t[1]], &q3 = uv[t[2]];
    a2[f] = 0.5 * cross(q2 - q1, q3 - q1);
    meanAbsA2 += std::abs(a2[f]);
  }
  meanAbsA2 /= std::max(1, nf);
  double sumA2 = 0, sumA3 = 0, sumL2 = 0, maxLinf = 0, angleSum = 0, angleMax = 1;
  for (int32_t f = 0; f < nf; ++f) {
    if (a2[f] < 0 && std::abs(a2[f]) > kDegenerateUV * meanAbsA2) ++m.flipped;
    else if (a2[f] <= kDegenerateUV * meanAbsA2) ++m.degenerate;
    sumA2 += std::abs(a2[f]);
    sumA3 += mesh.faceArea(f);
  }
  m.overlaps = boundaryOverlaps(mesh, uv);
  m.bijective = m.flipped == 0 && m.degenerate == 0 && m.overlaps == 0;
  std::vector<double> l2(nf, 0.0);
  for (int32_t f = 0; f < nf; ++f) {
    const double A3 = mesh.faceArea(f);
    if (a2[f] <= kDegenerateUV * meanAbsA2) {
      m.faceStretch[f] = std::numeric_limits<float>::infinity();
      continue;
    }
    if (!(A3 > 0)) continue;  // a zero-area 3D face stretches nothing
    const Triangle& t = mesh.triangle(f);
    const Vec2 &q1 = uv[t[0]], &q2 = uv[t[1]], &q3 = uv[t[2]];
    const Vec3 &p1 = mesh.position(t[0]), &p2 = mesh.position(t[1]), &p3 = mesh.position(t[2]);
    const double A = 2 * a2[f];
    const Vec3 Ss = (p1 * (q2.y - q3.y) + p2 * (q3.y - q1.y) + p3 * (q1.y - q2.y)) / A;
    const Vec3 St = (p1 * (q3.x - q2.x) + p2 * (q1.x - q3.x) + p3 * (q2.x - q1.x)) / A;
    const double a = dot(Ss, Ss), b = dot(Ss, St), c = dot(St, St);
    const double root = std::sqrt((a - c) * (a - c) + 4 * b * b);
    l2[f] = std::sqrt((a + c) / 2);
    const double linf = std::sqrt(((a + c) + root) / 2);
    const double gamma = std::sqrt(std::max(0.0, ((a + c) - root) / 2));
    sumL2 += l2[f] * l2[f] * A3;
    maxLinf = std::max(maxLinf, linf);
    const double conformal = gamma > 0 ? linf / gamma : inf;
    angleSum += conformal * A3;
    angleMax = std::max(angleMax, conformal);
    const double sigma = (std::abs(a2[f]) / sumA2) / (A3 / sumA3);
    const double areaRatio = std::max(sigma, 1 / sigma);
    m.areaDistortionMax = std::max(m.areaDistortionMax, areaRatio);
  }
  const double scale = std::sqrt(sumA2 / sumA3);
  for (int32_t f = 0; f < nf; ++f)
    if (m.faceStretch[f] == 0.0f) m.faceStretch[f] = static_cast<float>(l2[f] * scale);
  double areaSum = 0;
  for (int32_t f = 0; f < nf; ++f) {
    const double A3 = mesh.faceArea(f);
    if (!(A3 > 0) || a2[f] <= kDegenerateUV * meanAbsA2) continue;
    const double sigma = (std::abs(a2[f]) / sumA2) / (A3 / sumA3);
    areaSum += std::max(sigma, 1 / sigma) * A3;
  }
  m.areaDistortionMean = sumA3 > 0 ? areaSum / sumA3 : 1;
  m.angleDistortionMean = sumA3 > 0 ? angleSum / sumA3 : 1;
  m.angleDistortionMax = angleMax;
  if (m.bijective) {
    m.l2 = std::sqrt(sumL2 / sumA3) * scale;
    m.linf = maxLinf * scale;
  } else {
    m.l2 = m.linf = inf;
  }
  return m;
}

}  // namespace straightest
