// Meshes with known geometry for the core tests: flat grids in several triangulations (also almost flat,
// or with cells cut out), an L-shaped domain, an icosphere, and any mesh scaled.
#pragma once
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "straightest/mesh/samples.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest::testing {

inline constexpr double kPi = 3.14159265358979323846;

inline TriMesh buildOrFail(std::vector<Vec3> p, std::vector<Triangle> t) {
  auto mesh = TriMesh::build(std::move(p), std::move(t));
  if (!mesh) throw std::runtime_error("test mesh invalid: " + mesh.error().message);
  return std::move(mesh).value();
}

enum class GridPattern { Regular, UnionJack, Jittered };

/// An n × n vertex grid over [0, n−1]² mapped through lift(x, y) (default: the plane z = 0).
/// Regular: every square split along the same diagonal. UnionJack: alternating diagonals.
/// Jittered: interior vertices moved randomly by up to 0.25 (triangulation stays valid).
template <class Lift>
TriMesh grid(int n, GridPattern pattern, Lift lift, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  return makeGrid(
      n,
      [&](int i, int j) {
        double x = i, y = j;
        if (pattern == GridPattern::Jittered && i > 0 && j > 0 && i < n - 1 && j < n - 1) {
          x += jitter(rng);
          y += jitter(rng);
        }
        return lift(x, y);
      },
      pattern == GridPattern::UnionJack ? GridDiagonals::Alternating : GridDiagonals::Same);
}

inline TriMesh flatGrid(int n, GridPattern pattern) {
  return grid(n, pattern, [](double x, double y) { return Vec3{x, y, 0}; });
}

/// A flat n × n grid whose heights are noise of the given amplitude (jittered triangulation).
inline TriMesh almostFlatGrid(int n, double amplitude, unsigned seed = 5) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-amplitude, amplitude);
  return grid(n, GridPattern::Jittered, [&](double x, double y) { return Vec3{x, y, noise(rng)}; });
}

/// The mesh with every position multiplied by s (same triangles, same vertex order).
inline TriMesh scaled(const TriMesh& mesh, double s) {
  std::vector<Vec3> p;
  for (const Vec3& x : mesh.positions()) p.push_back(x * s);
  return buildOrFail(p, mesh.triangles());
}

/// A flat n × n vertex grid of unit cells, keeping the cells (column, row of the lower-left corner) for
/// which keep(i, j) holds; each cell split along its rising diagonal.
template <class Keep>
TriMesh gridOfCells(int n, Keep keep) {
  std::vector<Vec3> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p.push_back({double(i), double(j), 0});
  std::vector<Triangle> t;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (!keep(i, j)) continue;
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return buildOrFail(std::move(p), std::move(t));
}

/// A flat 9 × 9 vertex grid (8 × 8 cells) without the cells listed, as (column, row) of their lower-left corner.
inline TriMesh gridWithout(const std::vector<std::array<int, 2>>& removed) {
  return gridOfCells(9, [&](int i, int j) {
    for (const auto& c : removed)
      if (c[0] == i && c[1] == j) return false;
    return true;
  });
}

/// The halfedge from vertex a to vertex b, or -1 when no face has that edge in that direction.
inline int32_t findHalfedge(const TriMesh& mesh, int32_t a, int32_t b) {
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h)
    if (mesh.tail(h) == a && mesh.head(h) == b) return h;
  return -1;
}

/// An L-shaped flat domain: the grid [0, 2m]² without the square (m, 2m]² (m cells a side).
inline TriMesh lShape(int m) {
  return gridOfCells(2 * m + 1, [m](int i, int j) { return i < m || j < m; });  // without the cut-out quadrant
}

/// An icosphere of radius 1 (subdivisions: 0 → 12 vertices, 3 → 642).
inline TriMesh icosphere(int subdivisions) { return makeIcosphere(1.0, subdivisions); }

/// The length of a polyline through `points`.
inline double polylineLength(const std::vector<Vec3>& points) {
  double length = 0;
  for (size_t i = 1; i < points.size(); ++i) length += norm(points[i] - points[i - 1]);
  return length;
}

/// The boundary surface of a set of unit voxels (cells given by their lowest corner): every voxel side
/// with no voxel behind it is a square split into two triangles, facing out; lattice points are shared.
/// The voxels must not touch only along an edge or at a corner (that surface would not be manifold).
inline TriMesh voxelSurface(const std::vector<std::array<int, 3>>& cells) {
  std::map<std::array<int, 3>, int32_t> index;
  std::vector<Vec3> p;
  auto vertex = [&](std::array<int, 3> c) {
    auto [it, added] = index.emplace(c, int32_t(p.size()));
    if (added) p.push_back({double(c[0]), double(c[1]), double(c[2])});
    return it->second;
  };
  auto filled = [&](std::array<int, 3> c) {
    for (const auto& d : cells)
      if (d == c) return true;
    return false;
  };
  std::vector<Triangle> t;
  for (const auto& c : cells)
    for (int axis = 0; axis < 3; ++axis)
      for (int side : {-1, 1}) {
        std::array<int, 3> neighbour = c;
        neighbour[axis] += side;
        if (filled(neighbour)) continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // e_u × e_v = e_axis
        std::array<int, 3> base = c;
        if (side > 0) base[axis] += 1;
        std::array<std::array<int, 3>, 4> corner{base, base, base, base};
        corner[1][u] += 1;
        corner[2][u] += 1, corner[2][v] += 1;
        corner[3][v] += 1;
        std::array<int32_t, 4> q{vertex(corner[0]), vertex(corner[1]), vertex(corner[2]), vertex(corner[3])};
        if (side < 0) std::swap(q[1], q[3]);  // face −e_axis
        t.push_back({q[0], q[1], q[2]});
        t.push_back({q[0], q[2], q[3]});
      }
  return buildOrFail(std::move(p), std::move(t));
}

/// A closed surface of genus g: a 3 × (2g+1) × 1 slab of voxels with g holes punched through it (g = 0: a
/// 3 × 1 × 1 bar).
inline TriMesh genusSlab(int g) {
  std::vector<std::array<int, 3>> cells;
  for (int y = 0; y < 2 * g + 1; ++y)
    for (int x = 0; x < 3; ++x)
      if (!(x == 1 && y % 2 == 1)) cells.push_back({x, y, 0});
  return voxelSurface(cells);
}

/// A finger like an animal's leg: a closed tube of 8-vertex rings 0.8 apart, radius 1, `rings` rings,
/// capped at one end and open at the other (its only boundary). A convex-combination map from the open
/// end shrinks the rings geometrically towards the tip, so their areas underflow to zero.
inline TriMesh finger(int rings) {
  const int segments = 8;
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  for (int k = 0; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const double angle = 2 * kPi * (s + 0.5 * k) / segments;
      p.push_back({std::cos(angle), std::sin(angle), 0.8 * k});
    }
  p.push_back({0, 0, 0.8 * rings});
  for (int k = 0; k + 1 < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const int a = k * segments + s, b = k * segments + (s + 1) % segments;
      t.push_back({a, b, a + segments});
      t.push_back({b, b + segments, a + segments});
    }
  const int tip = rings * segments, last = (rings - 1) * segments;
  for (int s = 0; s < segments; ++s) t.push_back({last + s, last + (s + 1) % segments, tip});
  return testing::buildOrFail(p, t);
}

}  // namespace straightest::testing
