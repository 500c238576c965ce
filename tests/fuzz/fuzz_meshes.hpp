// Random valid meshes from fuzzer bytes, shared by fuzz_trace and fuzz_param. Every generator
// produces positions + triangles that TriMesh::build accepts; a random similarity transform
// (rotation, scale 1e-6..1e6, offset) is applied so tolerances are exercised at every scale.
#pragma once
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <limits>

#include "fuzz_common.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/mesh/surface_point.hpp"

namespace fuzz {

inline constexpr double kPi = 3.14159265358979323846;

struct RandomMesh {
  std::vector<Vec3> P;
  std::vector<Triangle> T;
  bool flatConvex = false;  // planar with a convex boundary (straight paths must reach every target)
  bool disk = false;        // a topological disk by construction
  const char* kind = "";
};

/// A height field over an n × n grid from makeGrid: heights from the bytes (quantized, so exact
/// coincidences and collinear points happen), interior vertices jittered in the plane by less than a
/// quarter cell (the triangulation stays valid). flat: all heights zero.
inline RandomMesh heightGrid(FuzzedDataProvider& in, int maxN, bool allowFlat = true) {
  RandomMesh r;
  r.kind = "grid";
  const int n = in.ConsumeIntegralInRange(2, maxN);
  const auto diagonals = in.ConsumeBool() ? GridDiagonals::Alternating : GridDiagonals::Same;
  static const double scales[] = {0.0, 1e-3, 0.05, 0.3, 1.0, 4.0};
  double heightScale = scales[in.ConsumeIntegralInRange<size_t>(0, 5)];
  if (!allowFlat && heightScale == 0) heightScale = 0.3;
  static const double jitters[] = {0.0, 0.1, 0.24};
  const double jitter = jitters[in.ConsumeIntegralInRange<size_t>(0, 2)];
  const bool smooth = in.ConsumeBool();  // heights from a few bumps instead of per-vertex noise
  double bump[3][4];
  for (auto& b : bump)
    for (double& x : b) x = in.ConsumeProbability<double>();
  const TriMesh grid = makeGrid(
      n,
      [&](int i, int j) {
        double x = i, y = j, z = 0;
        if (jitter > 0 && i > 0 && j > 0 && i < n - 1 && j < n - 1) {
          x += jitter * (in.ConsumeIntegralInRange(0, 254) / 127.0 - 1);
          y += jitter * (in.ConsumeIntegralInRange(0, 254) / 127.0 - 1);
        }
        if (heightScale > 0) {
          if (smooth) {
            for (const auto& b : bump) {
              const double cx = b[0] * (n - 1), cy = b[1] * (n - 1), s = 0.5 + b[2] * n;
              z += (b[3] - 0.5) * 2 * (n - 1) * std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (s * s));
            }
            z *= heightScale;
          } else {
            z = heightScale * (in.ConsumeIntegralInRange(0, 255) - 128) / 32.0;
          }
        }
        return Vec3{x, y, z};
      },
      diagonals);
  r.P = grid.positions();
  r.T = grid.triangles();
  r.flatConvex = heightScale == 0;
  r.disk = true;
  return r;
}

/// makeSphericalCap; polar angles up to 0.995π (nearly closed: a tiny boundary loop).
inline RandomMesh cap(FuzzedDataProvider& in, bool allowClosing) {
  RandomMesh r;
  r.kind = "cap";
  const int rings = in.ConsumeIntegralInRange(1, 6);
  const double theta = (allowClosing ? 0.995 * kPi : 0.9 * kPi) * (0.05 + 0.95 * in.ConsumeProbability<double>());
  const TriMesh m = makeSphericalCap(1.0, theta, rings);
  r.P = m.positions();
  r.T = m.triangles();
  for (Vec3& p : r.P) p = p * (1 + 0.3 * (in.ConsumeIntegralInRange(0, 255) / 255.0 - 0.5) * in.ConsumeBool());
  r.disk = true;
  return r;
}

/// A closed bumpy sphere (latitude/longitude with two poles) or an open tube (two boundary loops).
inline RandomMesh sphereOrTube(FuzzedDataProvider& in) {
  RandomMesh r;
  const bool tube = in.ConsumeBool();
  r.kind = tube ? "tube" : "sphere";
  const int rings = in.ConsumeIntegralInRange(tube ? 2 : 1, 6), segments = in.ConsumeIntegralInRange(3, 10);
  const double bumpiness = in.ConsumeIntegralInRange(0, 3) * 0.1;
  auto radius = [&] { return 1 + bumpiness * (in.ConsumeIntegralInRange(0, 255) / 127.5 - 1); };
  // ring k (k = 0..rings-1) at height / latitude, `segments` vertices each
  for (int k = 0; k < rings; ++k) {
    const double lat = tube ? 0 : -kPi / 2 + kPi * (k + 1) / (rings + 1);
    const double z = tube ? 2.0 * k / std::max(1, rings - 1) - 1 : std::sin(lat);
    for (int s = 0; s < segments; ++s) {
      const double a = 2 * kPi * s / segments, rr = radius() * (tube ? 1 : std::cos(lat));
      r.P.push_back({rr * std::cos(a), rr * std::sin(a), z});
    }
  }
  for (int k = 0; k + 1 < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const int a = k * segments + s, b = k * segments + (s + 1) % segments, c = a + segments, d = b + segments;
      r.T.push_back({a, b, d});
      r.T.push_back({a, d, c});
    }
  if (!tube) {
    const int south = static_cast<int>(r.P.size()), north = south + 1;
    r.P.push_back({0, 0, -radius()});
    r.P.push_back({0, 0, radius()});
    const int top = (rings - 1) * segments;
    for (int s = 0; s < segments; ++s) {
      r.T.push_back({south, (s + 1) % segments, s});
      r.T.push_back({north, top + s, top + (s + 1) % segments});
    }
  }
  return r;
}

/// Rotation, uniform scale and offset; returns the built mesh (generators always build).
inline TriMesh transformAndBuild(FuzzedDataProvider& in, RandomMesh& r) {
  const double a = 2 * kPi * in.ConsumeProbability<double>(), b = kPi * in.ConsumeProbability<double>(),
               c = 2 * kPi * in.ConsumeProbability<double>();
  static const double scales[] = {1.0, 1e-6, 1e-3, 1e3, 1e6, 1.0, 1.0, 1.0};
  const double scale = scales[in.ConsumeIntegralInRange<size_t>(0, 7)];
  static const double offsets[] = {0.0, 0.0, 1.0, 100.0, 1e3};
  const double offset = offsets[in.ConsumeIntegralInRange<size_t>(0, 4)];
  const bool rotate = in.ConsumeBool();
  auto rot = [](Vec3 p, int axis, double t) {
    const double cs = std::cos(t), sn = std::sin(t);
    if (axis == 0) return Vec3{p.x, cs * p.y - sn * p.z, sn * p.y + cs * p.z};
    if (axis == 1) return Vec3{cs * p.x + sn * p.z, p.y, -sn * p.x + cs * p.z};
    return Vec3{cs * p.x - sn * p.y, sn * p.x + cs * p.y, p.z};
  };
  for (Vec3& p : r.P) {
    if (rotate) p = rot(rot(rot(p, 2, a), 0, b), 2, c);
    p = (p + Vec3{offset, -0.5 * offset, 0.25 * offset}) * scale;
  }
  auto built = TriMesh::build(r.P, r.T);
  FUZZ_CHECK(built.ok(), "generated %s mesh rejected: %s: %s", r.kind, errorCodeName(built.error().code),
             built.error().message.c_str());
  return std::move(built).value();
}

/// A surface point from the bytes: a vertex, an edge point (t at 0, 1, 1/2, near the ends or
/// anywhere) or a face point (barycentric coordinates with zeros now and then); valid.
inline SurfacePoint randomPoint(FuzzedDataProvider& in, const TriMesh& m) {
  switch (in.ConsumeIntegralInRange(0, 2)) {
    case 0: return SurfacePoint::vertex(in.ConsumeIntegralInRange<int32_t>(0, m.numVertices() - 1));
    case 1: {
      static const double ts[] = {0.0, 1.0, 0.5, 1e-13, 1 - 1e-13, 1e-7, -1.0};
      double t = ts[in.ConsumeIntegralInRange<size_t>(0, 6)];
      if (t < 0) t = in.ConsumeProbability<double>();
      return SurfacePoint::edge(in.ConsumeIntegralInRange<int32_t>(0, 3 * m.numFaces() - 1), t);
    }
    default: {
      std::array<double, 3> b{};
      double sum = 0;
      for (double& x : b) {
        x = in.ConsumeIntegralInRange(0, 3) == 0 ? 0.0 : in.ConsumeProbability<double>();
        sum += x;
      }
      if (!(sum > 0)) b = {1, 0, 0}, sum = 1;
      for (double& x : b) x /= sum;
      return SurfacePoint::face(in.ConsumeIntegralInRange<int32_t>(0, m.numFaces() - 1), b);
    }
  }
}

/// An invalid surface point: index out of range, t outside [0, 1] or NaN, bad barycentrics.
inline SurfacePoint invalidPoint(FuzzedDataProvider& in, const TriMesh& m) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0: return SurfacePoint::vertex(in.ConsumeBool() ? -1 : m.numVertices());
    case 1: return SurfacePoint::edge(in.ConsumeBool() ? -1 : 3 * m.numFaces(), 0.5);
    case 2: return SurfacePoint::edge(0, in.ConsumeBool() ? 1.5 : (in.ConsumeBool() ? -0.5 : nan));
    case 3: return SurfacePoint::face(in.ConsumeBool() ? -1 : m.numFaces(), {1, 0, 0});
    case 4: return SurfacePoint::face(0, {0.5, 0.5, 0.5});
    case 5: return SurfacePoint::face(0, {1.5, -0.5, 0});
    default: return SurfacePoint::face(0, {nan, 0.5, 0.5});
  }
}

}  // namespace fuzz
