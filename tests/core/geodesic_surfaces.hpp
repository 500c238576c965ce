// Developable test surfaces whose geodesics are known in closed form: a polyhedral cone (a pyramid whose
// lateral faces are finely triangulated, flat everywhere but at the apex) with its unrolled coordinates,
// and an open prism (a polygonal cylinder) with its unrolled strip coordinates.
#pragma once
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "test_meshes.hpp"

namespace straightest::testing {

/// A pyramid over a regular `sides`-gon of radius r at height 0 with its apex at (0, 0, height), the base
/// open; each lateral face split into k² triangles. Unrolled, the surface is the fan of `sides` triangles of
/// angle `faceAngle` around the apex: vertex i sits at polar (radius[i], angle[i]) with angle in [0, total).
struct Cone {
  TriMesh mesh;
  int32_t apex = 0;
  double faceAngle = 0, totalAngle = 0;
  std::vector<double> radius, angle;

  /// The distance between two vertices in the unrolled cone (the straight segment, shorter way around;
  /// valid while the total angle's half is below π).
  double unrolledDistance(int32_t a, int32_t b) const {
    double delta = std::fabs(angle[a] - angle[b]);
    delta = std::min(delta, totalAngle - delta);
    return std::sqrt(
        std::max(0.0, radius[a] * radius[a] + radius[b] * radius[b] - 2 * radius[a] * radius[b] * std::cos(delta)));
  }
};

inline Cone cone(int sides, double r, double height, int k) {
  struct {
    double faceAngle = 0, totalAngle = 0;
    std::vector<double> radius, angle;
  } c;
  const Vec3 apex{0, 0, height};
  auto base = [&](int i) {
    const double t = 2 * kPi * (i % sides) / sides;
    return Vec3{r * std::cos(t), r * std::sin(t), 0};
  };
  const Vec3 b0 = base(0) - apex, b1 = base(1) - apex;
  c.faceAngle = std::atan2(norm(cross(b0, b1)), dot(b0, b1));
  c.totalAngle = sides * c.faceAngle;
  std::vector<Vec3> p;
  std::map<std::tuple<int, int>, int32_t> index;  // (ray or face·k + offset, step): one vertex per lattice point
  auto vertex = [&](int face, int a, int b) {
    // a steps along ray `face`, b along ray `face + 1`; points on a ray are keyed by the ray alone.
    std::tuple<int, int> key;
    if (a + b == 0) key = {-1, 0};
    else if (b == 0) key = {(face % sides) * (k + 1), a};
    else if (a == 0) key = {((face + 1) % sides) * (k + 1), b};
    else key = {sides * (k + 1) + face * (k + 1) * (k + 1) + a, b};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    const Vec3 x = apex + (base(face) - apex) * (double(a) / k) + (base(face + 1) - apex) * (double(b) / k);
    const double l = norm(b0);
    // Unrolled: the ray `face` at angle face·faceAngle.
    const double ta = face * c.faceAngle, tb = (face + 1) * c.faceAngle;
    const double ux = l * (a * std::cos(ta) + b * std::cos(tb)) / k, uy = l * (a * std::sin(ta) + b * std::sin(tb)) / k;
    double phi = std::atan2(uy, ux);
    if (phi < 0) phi += 2 * kPi;
    if (a == 0 && (face + 1) % sides == 0) phi = 0;  // the seam ray
    if (a + b == 0) phi = 0;
    c.radius.push_back(std::hypot(ux, uy));
    c.angle.push_back(std::fmod(phi, c.totalAngle));
    p.push_back(x);
    return index[key] = static_cast<int32_t>(p.size() - 1);
  };
  std::vector<Triangle> t;
  for (int f = 0; f < sides; ++f)
    for (int a = 0; a < k; ++a)
      for (int b = 0; a + b < k; ++b) {
        t.push_back({vertex(f, a, b), vertex(f, a + 1, b), vertex(f, a, b + 1)});
        if (a + b + 2 <= k) t.push_back({vertex(f, a + 1, b), vertex(f, a + 1, b + 1), vertex(f, a, b + 1)});
      }
  const int32_t apexIndex = index[{-1, 0}];
  return Cone{buildOrFail(std::move(p), std::move(t)),
              apexIndex,
              c.faceAngle,
              c.totalAngle,
              std::move(c.radius),
              std::move(c.angle)};
}

/// An open prism: `around` vertices on a circle of radius r per ring, `rings` rings `dz` apart, each quad
/// split by alternating diagonals. Vertex (ring j, position i) = j·around + i; unrolled at (i·side, j·dz).
struct Prism {
  TriMesh mesh;
  int around = 0;
  double side = 0, dz = 0;
  double perimeter() const { return around * side; }
  double unrolledDistance(int32_t a, int32_t b) const {
    double ds = std::fabs(double(a % around - b % around)) * side;
    ds = std::min(ds, perimeter() - ds);
    return std::hypot(ds, (a / around - b / around) * dz);
  }
};

inline Prism prism(int around, int rings, double r, double dz) {
  std::vector<Vec3> p;
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double t = 2 * kPi * i / around;
      p.push_back({r * std::cos(t), r * std::sin(t), j * dz});
    }
  std::vector<Triangle> t;
  for (int j = 0; j + 1 < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const int a = j * around + i, b = j * around + (i + 1) % around, c2 = a + around, d = b + around;
      if ((i + j) % 2 == 0) {
        t.push_back({a, b, d});
        t.push_back({a, d, c2});
      } else {
        t.push_back({a, b, c2});
        t.push_back({b, d, c2});
      }
    }
  return Prism{buildOrFail(std::move(p), std::move(t)), around, 2 * r * std::sin(kPi / around), dz};
}

}  // namespace straightest::testing
