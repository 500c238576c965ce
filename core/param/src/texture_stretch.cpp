// texture_stretch.cpp — Sander et al.'s stretch of a uv map, and the map's bijectivity checks.
// Faces are measured in chunks on every thread (parallel_for.hpp); every sum is a sum of per-chunk
// partial sums taken in chunk order, so the metrics are the same for any thread count.
#include "straightest/param/texture_stretch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "straightest/base/parallel_for.hpp"
#include "straightest/param/boundary_overlaps.hpp"

namespace straightest {

namespace {
constexpr size_t kFacesPerChunk = 16384;

/// One chunk's share of the metrics' sums, maxima and counts.
struct ChunkSums {
  double absA2 = 0, A3 = 0, l2 = 0, angle = 0, area = 0;
  double maxLinf = 0, angleMax = 1, areaMax = 1;
  int64_t flipped = 0, degenerate = 0;
};

/// The singular values Γ (linf) and γ (gamma) of face f's map from uv to 3D, and their root mean square
/// (l2): Sander et al.'s stretch. twiceArea is the face's signed uv area, doubled.
struct FaceStretch {
  double l2, linf, gamma;
};
FaceStretch faceStretch(const TriMesh& mesh, const std::vector<Vec2>& uv, int32_t f, double twiceArea) {
  const Triangle& t = mesh.triangle(f);
  const Vec2 &q1 = uv[t[0]], &q2 = uv[t[1]], &q3 = uv[t[2]];
  const Vec3 &p1 = mesh.position(t[0]), &p2 = mesh.position(t[1]), &p3 = mesh.position(t[2]);
  const double A = twiceArea;
  const Vec3 Ss = (p1 * (q2.y - q3.y) + p2 * (q3.y - q1.y) + p3 * (q1.y - q2.y)) / A;
  const Vec3 St = (p1 * (q3.x - q2.x) + p2 * (q1.x - q3.x) + p3 * (q2.x - q1.x)) / A;
  const double a = dot(Ss, Ss), b = dot(Ss, St), c = dot(St, St);
  const double root = std::sqrt((a - c) * (a - c) + 4 * b * b);
  return {std::sqrt((a + c) / 2), std::sqrt(((a + c) + root) / 2), std::sqrt(std::max(0.0, ((a + c) - root) / 2))};
}
}  // namespace

StretchMetrics textureStretch(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  StretchMetrics m;
  const int32_t nf = mesh.numFaces();
  const double inf = std::numeric_limits<double>::infinity();
  m.faceStretch.assign(nf, 0.0f);
  std::vector<double> a2(nf), l2(nf, 0.0);
  std::vector<ChunkSums> chunk(detail::chunkCount(nf, kFacesPerChunk));
  auto faces = [&](auto&& perChunk) {
    detail::parallelFor(nf, kFacesPerChunk, [&](size_t c, size_t begin, size_t end) {
      perChunk(chunk[c], static_cast<int32_t>(begin), static_cast<int32_t>(end));
    });
  };
  faces([&](ChunkSums& s, int32_t begin, int32_t end) {
    for (int32_t f = begin; f < end; ++f) {
      const Triangle& t = mesh.triangle(f);
      const Vec2 &q1 = uv[t[0]], &q2 = uv[t[1]], &q3 = uv[t[2]];
      a2[f] = 0.5 * cross(q2 - q1, q3 - q1);
      s.absA2 += std::abs(a2[f]);
      s.A3 += mesh.faceArea(f);
    }
  });
  double sumA2 = 0, sumA3 = 0;
  for (const ChunkSums& s : chunk) {
    sumA2 += s.absA2;
    sumA3 += s.A3;
  }
  const double meanAbsA2 = sumA2 / std::max(1, nf);
  faces([&](ChunkSums& s, int32_t begin, int32_t end) {
    for (int32_t f = begin; f < end; ++f) {
      if (a2[f] < 0 && std::abs(a2[f]) > kDegenerateUV * meanAbsA2) ++s.flipped;
      else if (a2[f] <= kDegenerateUV * meanAbsA2) ++s.degenerate;
      const double A3 = mesh.faceArea(f);
      if (a2[f] <= kDegenerateUV * meanAbsA2) {
        m.faceStretch[f] = std::numeric_limits<float>::infinity();
        continue;
      }
      if (!(A3 > 0)) continue;  // a zero-area 3D face stretches nothing
      const FaceStretch stretch = faceStretch(mesh, uv, f, 2 * a2[f]);
      l2[f] = stretch.l2;
      s.l2 += l2[f] * l2[f] * A3;
      s.maxLinf = std::max(s.maxLinf, stretch.linf);
      const double conformal = stretch.gamma > 0 ? stretch.linf / stretch.gamma : inf;
      s.angle += conformal * A3;
      s.angleMax = std::max(s.angleMax, conformal);
      const double sigma = (std::abs(a2[f]) / sumA2) / (A3 / sumA3);
      const double areaRatio = std::max(sigma, 1 / sigma);
      s.areaMax = std::max(s.areaMax, areaRatio);
      s.area += areaRatio * A3;
    }
  });
  double sumL2 = 0, maxLinf = 0, angleSum = 0, angleMax = 1, areaSum = 0;
  for (const ChunkSums& s : chunk) {
    m.flipped += s.flipped;
    m.degenerate += s.degenerate;
    sumL2 += s.l2;
    maxLinf = std::max(maxLinf, s.maxLinf);
    angleSum += s.angle;
    angleMax = std::max(angleMax, s.angleMax);
    m.areaDistortionMax = std::max(m.areaDistortionMax, s.areaMax);
    areaSum += s.area;
  }
  m.overlaps = boundaryOverlaps(mesh, uv);
  m.bijective = m.flipped == 0 && m.degenerate == 0 && m.overlaps == 0;
  const double scale = std::sqrt(sumA2 / sumA3);
  faces([&](ChunkSums&, int32_t begin, int32_t end) {
    for (int32_t f = begin; f < end; ++f)
      if (m.faceStretch[f] == 0.0f) m.faceStretch[f] = static_cast<float>(l2[f] * scale);
  });
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
