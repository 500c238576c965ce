// Built-in sample meshes (see samples.hpp). Each generator builds positions and triangles and goes
// through TriMesh::build like any file would.
#include "straightest/mesh/samples.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace straightest {
namespace {

TriMesh buildOrDie(std::vector<Vec3> positions, std::vector<Triangle> triangles) {
  auto mesh = TriMesh::build(std::move(positions), std::move(triangles));
  // The generators are ours: a failure here is a programmer error.
  if (!mesh) throw std::logic_error("sample generator produced an invalid mesh: " + mesh.error().message);
  return std::move(mesh).value();
}

/// Concentric rings around a center vertex over the unit disk (ring i has 6*i vertices at radius
/// i/rings), mapped through `lift(x, y) -> Vec3`. Gives well-shaped triangles and a round boundary.
template <class Lift>
TriMesh diskMesh(int rings, Lift lift) {
  std::vector<Vec3> positions{lift(0.0, 0.0)};
  std::vector<Triangle> triangles;
  auto ringStart = [](int i) { return i == 0 ? 0 : 1 + 3 * i * (i - 1); };  // vertices before ring i
  for (int i = 1; i <= rings; ++i) {
    const int count = 6 * i;
    for (int j = 0; j < count; ++j) {
      const double a = 2 * kPi * j / count, r = static_cast<double>(i) / rings;
      positions.push_back(lift(r * std::cos(a), r * std::sin(a)));
    }
  }
  for (int i = 1; i <= rings; ++i) {
    const int outer = ringStart(i), inner = ringStart(i - 1);
    const int nOuter = 6 * i, nInner = i == 1 ? 1 : 6 * (i - 1), innerSteps = i == 1 ? 0 : nInner;
    // Walk both rings by angle; each step emits one triangle advancing the ring that lags behind.
    int a = 0, b = 0;
    while (a < nOuter || b < innerSteps) {
      const double angleOuter = static_cast<double>(a + 1) / nOuter;
      const double angleInner = i == 1 ? 2.0 : static_cast<double>(b + 1) / nInner;
      const int o0 = outer + a % nOuter, o1 = outer + (a + 1) % nOuter;
      const int i0 = inner + (i == 1 ? 0 : b % nInner), i1 = inner + (i == 1 ? 0 : (b + 1) % nInner);
      if (b >= innerSteps || (a < nOuter && angleOuter <= angleInner)) {
        triangles.push_back({o0, o1, i0});
        ++a;
      } else {
        triangles.push_back({i0, o0, i1});
        ++b;
      }
    }
  }
  return buildOrDie(std::move(positions), std::move(triangles));
}

double mountainHeight(double x, double y) {
  auto bump = [](double x, double y, double cx, double cy, double s, double h) {
    return h * std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * s * s));
  };
  return bump(x, y, 0.1, 0.05, 0.35, 0.8) + bump(x, y, -0.5, 0.45, 0.25, 0.45) + bump(x, y, 0.55, -0.5, 0.2, 0.35);
}

double faceHeight(double x, double y) {
  auto bump = [](double x, double y, double cx, double cy, double sx, double sy, double h) {
    return h * std::exp(-((x - cx) * (x - cx) / (2 * sx * sx) + (y - cy) * (y - cy) / (2 * sy * sy)));
  };
  const double dome = 0.45 * std::sqrt(std::max(0.0, 1.0 - 0.8 * (x * x + y * y)));
  return dome + bump(x, y, 0, 0.0, 0.07, 0.25, 0.28)                                        // nose
         + bump(x, y, -0.3, 0.35, 0.2, 0.06, 0.08)                                          // brows
         + bump(x, y, 0.3, 0.35, 0.2, 0.06, 0.08) - bump(x, y, -0.3, 0.2, 0.1, 0.06, 0.1)   // eye sockets
         - bump(x, y, 0.3, 0.2, 0.1, 0.06, 0.1) + bump(x, y, -0.4, -0.2, 0.18, 0.18, 0.07)  // cheeks
         + bump(x, y, 0.4, -0.2, 0.18, 0.18, 0.07) + bump(x, y, 0, -0.5, 0.2, 0.05, 0.05)   // lips
         + 0.015 * std::sin(9 * x) * std::cos(7 * y);                                       // skin bumps
}

/// The "holes" sample: a low dome over the unit disk with three round holes (faces whose centroid falls
/// inside one of three circles removed; the vertices left without a face dropped).
TriMesh domeWithThreeHoles() {
  const TriMesh disk = diskMesh(24, [](double x, double y) { return Vec3{x, y, 0.3 * (1 - x * x - y * y)}; });
  const double holes[3][3] = {{0.35, 0.2, 0.2}, {-0.4, 0.25, 0.15}, {0.0, -0.45, 0.18}};  // centre x, y, radius
  std::vector<int32_t> renumber(disk.numVertices(), -1);
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  for (const Triangle& t : disk.triangles()) {
    const Vec3 c = (disk.position(t[0]) + disk.position(t[1]) + disk.position(t[2])) / 3;
    bool inHole = false;
    for (const auto& h : holes)
      inHole = inHole || (c.x - h[0]) * (c.x - h[0]) + (c.y - h[1]) * (c.y - h[1]) < h[2] * h[2];
    if (inHole) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      if (renumber[t[k]] < 0) {
        renumber[t[k]] = static_cast<int32_t>(positions.size());
        positions.push_back(disk.position(t[k]));
      }
      kept[k] = renumber[t[k]];
    }
    triangles.push_back(kept);
  }
  return buildOrDie(std::move(positions), std::move(triangles));
}

}  // namespace

std::vector<std::string> sampleNames() { return {"mountain", "cap", "saddle", "face", "holes", "sphere", "torus"}; }

TriMesh makeGrid(int n, const std::function<Vec3(int i, int j)>& vertex, GridDiagonals diagonals) {
  if (n < 2) n = 2;
  std::vector<Vec3> positions;
  positions.reserve(static_cast<size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) positions.push_back(vertex(i, j));
  std::vector<Triangle> triangles;
  triangles.reserve(2 * static_cast<size_t>(n - 1) * (n - 1));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if (diagonals == GridDiagonals::Alternating && (i + j) % 2 == 1) {
        triangles.push_back({a, b, c});
        triangles.push_back({b, d, c});
      } else {
        triangles.push_back({a, b, d});
        triangles.push_back({a, d, c});
      }
    }
  return buildOrDie(std::move(positions), std::move(triangles));
}

TriMesh makeHeightField(int n) {
  if (n < 2) n = 2;
  return makeGrid(
      n,
      [n](int i, int j) {
        const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
        return Vec3{x, y, mountainHeight(x, y)};
      },
      GridDiagonals::Alternating);
}

TriMesh makeSphericalCap(double radius, double thetaMax, int rings) {
  return diskMesh(rings, [&](double x, double y) {
    const double r = std::sqrt(x * x + y * y), theta = r * thetaMax, phi = std::atan2(y, x);
    return Vec3{radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                radius * std::cos(theta)};
  });
}

TriMesh makeIcosphere(double radius, int subdivisions) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> p{{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (auto& v : p) v = normalized(v);
  std::vector<Triangle> t{{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                          {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    // Each edge's midpoint once, shared by its two faces.
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(normalized(p[a] + p[b]));
      return mid[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<Triangle> next;
    next.reserve(4 * t.size());
    for (const auto& f : t) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    t = std::move(next);
  }
  for (auto& v : p) v = v * radius;
  return buildOrDie(std::move(p), std::move(t));
}

TriMesh makeTorus(double R, double r, int around, int tube) {
  around = std::max(around, 3);
  tube = std::max(tube, 3);
  std::vector<Vec3> positions;
  positions.reserve(static_cast<size_t>(around) * tube);
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2 * kPi * i / around, v = 2 * kPi * j / tube;
      positions.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  std::vector<Triangle> triangles;
  triangles.reserve(2 * positions.size());
  auto index = [&](int i, int j) { return static_cast<int32_t>((i % around) * tube + j % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      // Counter-clockwise seen from outside: u grows along x, v around the tube.
      triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  return buildOrDie(std::move(positions), std::move(triangles));
}

Expected<TriMesh> makeSample(const std::string& name) {
  if (name == "mountain") return makeHeightField(50);
  if (name == "cap") return makeSphericalCap(1.0, kPi / 3, 16);
  if (name == "saddle") return diskMesh(16, [](double x, double y) { return Vec3{x, y, x * x - y * y}; });
  if (name == "face") return diskMesh(20, [](double x, double y) { return Vec3{0.8 * x, y, faceHeight(0.8 * x, y)}; });
  if (name == "holes") return domeWithThreeHoles();
  if (name == "sphere") return makeIcosphere(1.0, 4);
  if (name == "torus") return makeTorus(1.0, 0.4, 48, 24);
  std::string names;
  for (const auto& n : sampleNames()) names += (names.empty() ? "" : ", ") + n;
  return Error{ErrorCode::InvalidArgument, "unknown sample '" + name + "' (available: " + names + ")"};
}

}  // namespace straightest
