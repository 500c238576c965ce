// The boundary polygon of a map: convexify lifts the points a chord would collapse, the measured
// boundary stays bijective where a boundary edge points at the source, keeps every ear of a jagged boundary
// above its stated least area, and gives failed traces radii between the straight line and the edge graph that
// are close to the true geodesic distance.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/boundary_map.hpp"
#include "straightest/param/parameterize.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

TEST(Convexify, BulgesAChordBetweenTwoHullCornersWithAPointBetween) {
  // A, B, C on one hull edge (A and C corners), chord A–C: triangle ABC would collapse unless B is lifted.
  std::vector<Vec2> pts{{-1, -1}, {0, -1}, {1, -1}, {1, 1}, {-1, 1}};
  ASSERT_EQ(convexify(pts, {{0, 2}}), 0);
  EXPECT_LT(pts[1][1], -1 - 1e-3);  // lifted outward (below the edge y = −1)
  EXPECT_DOUBLE_EQ(pts[0][1], -1);
  EXPECT_DOUBLE_EQ(pts[2][1], -1);
}

TEST(Convexify, TreatsARoundingMadeHullCornerAsStraight) {
  // B sticks out of the edge AC by 1e-13 (a corner turning by a sine of ~1e-13): the hull must still
  // see one edge A–C and lift B, else the chord A–C keeps a collapsed triangle.
  std::vector<Vec2> pts{{-1, -1}, {0, -1 - 1e-13}, {1, -1}, {1, 1}, {-1, 1}};
  ASSERT_GE(convexify(pts, {{0, 2}}), 0);
  EXPECT_LT(pts[1][1], -1 - 1e-3);
}

TEST(MeasuredBoundary, AnEdgePointingAtTheSourceKeepsTheMapBijective) {
  // Removing cell (7, 3) puts the boundary edge (8, 4) → (7, 4) on the ray from S = (4, 4): both ends
  // had the same polar angle and landed on one point of the hull, collapsing a triangle.
  const TriMesh mesh = testing::gridWithout({{7, 3}});
  const SurfacePoint source = SurfacePoint::vertex(4 * 9 + 4);
  const BoundaryMap boundary = measuredBoundary(mesh, source).value();
  // The polygon is convex and counter-clockwise, and no two consecutive points coincide.
  const size_t n = boundary.polygon.size();
  ASSERT_EQ(n, boundary.loop.size());
  double perimeter = 0;
  for (size_t i = 0; i < n; ++i) perimeter += norm(boundary.polygon[(i + 1) % n] - boundary.polygon[i]);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = boundary.polygon[i], b = boundary.polygon[(i + 1) % n], c = boundary.polygon[(i + 2) % n];
    EXPECT_GT(norm(b - a), 1e-6 * perimeter) << "points " << i << " and " << (i + 1) % n << " coincide";
    EXPECT_GE(cross(b - a, c - b), -1e-12 * perimeter * perimeter) << "turns clockwise at " << (i + 1) % n;
  }
  ParamOptions options;
  options.source = source;
  for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform}) {
    options.weights = w;
    auto p = parameterize(mesh, options);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_TRUE(p.value().metrics.bijective) << weightKindName(w) << ": " << p.value().metrics.flipped << " flipped, "
                                             << p.value().metrics.degenerate << " degenerate";
  }
}

/// A staircase disk: the unit cells of a 15 × 15 grid whose centres lie within 5.6 of the middle, lifted
/// through height(x, y). Each cell is split along its rising diagonal, so the convex steps of the staircase
/// are ears (faces whose three corners are on the boundary).
template <class Height>
TriMesh staircaseDisk(Height height) {
  const TriMesh flat = testing::gridOfCells(15,
                                            [](int i, int j) { return std::hypot(i + 0.5 - 7, j + 0.5 - 7) < 5.6; });
  std::vector<Vec3> p = flat.positions();
  for (Vec3& x : p) x.z = height(x.x - 7, x.y - 7);
  return testing::buildOrFail(p, flat.triangles());
}

double surfaceArea(const TriMesh& mesh) {
  double a = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) a += mesh.faceArea(f);
  return a;
}

void expectEveryEarAboveItsLeastArea(const TriMesh& mesh) {
  ASSERT_EQ(mesh.boundaryLoops().size(), 1u);
  const int32_t middle = 7 * 15 + 7;
  const BoundaryMap boundary = measuredBoundary(mesh, SurfacePoint::vertex(middle)).value();
  const std::vector<BoundaryEar> ears = boundaryEars(mesh, boundary.loop);
  int64_t faceEars = 0;
  for (const BoundaryEar& ear : ears) {
    if (std::abs(ear.area3D - 0.5) > 0.25) continue;  // a single grid triangle (on the bump, a little larger)
    ++faceEars;
  }
  ASSERT_GE(faceEars, 8) << "the staircase must have ears for this test to mean anything";
  const double area = surfaceArea(mesh);
  EXPECT_GE(worstEarRatio(boundary.polygon, ears, area), kEarAreaFraction);
  // Stated for every ear: its corners' triangle, at the map's scale (the polygon's area over the surface's).
  double twice = 0;
  const size_t n = boundary.polygon.size();
  for (size_t i = 0; i < n; ++i) twice += cross(boundary.polygon[i], boundary.polygon[(i + 1) % n]);
  const double scale = twice / 2 / area;
  for (const BoundaryEar& ear : ears) {
    const Vec2 a = boundary.polygon[ear.corners[0]], b = boundary.polygon[ear.corners[1]],
               c = boundary.polygon[ear.corners[2]];
    EXPECT_GE(std::abs(cross(b - a, c - a)) / 2, kEarAreaFraction * ear.area3D * scale)
        << "ear at loop positions " << ear.corners[0] << ", " << ear.corners[1] << ", " << ear.corners[2];
  }
  ParamOptions options;
  options.source = SurfacePoint::vertex(middle);
  const auto p = parameterize(mesh, options);
  ASSERT_TRUE(p.ok()) << p.error().message;
  EXPECT_TRUE(p.value().metrics.bijective);
  // Without the lift, the ears on the straight hull edges would be slivers and dominate the stretch.
  options.boundary = BoundaryKind::Circle;
  const auto circle = parameterize(mesh, options);
  ASSERT_TRUE(circle.ok()) << circle.error().message;
  EXPECT_LT(p.value().metrics.l2, circle.value().metrics.l2);
}

TEST(MeasuredBoundary, EveryEarOfAFlatStaircaseKeepsItsLeastArea) {
  expectEveryEarAboveItsLeastArea(staircaseDisk([](double, double) { return 0.0; }));
}

TEST(MeasuredBoundary, EveryEarOfAStaircaseOnABumpKeepsItsLeastArea) {
  expectEveryEarAboveItsLeastArea(staircaseDisk([](double x, double y) { return 2 * std::exp(-(x * x + y * y) / 8); }));
}

/// Checks fallbackRadii from the middle vertex of an n × n grid lifted by `place` against `exact` (the smooth
/// surface's geodesic distance): never above the edge graph, never below the straight line, and within the heat
/// method's accuracy (a few percent) of the exact value.
template <class Place, class Exact>
void expectFallbackRadiiNearTheGeodesic(int n, Place place, Exact exact) {
  const TriMesh mesh = makeGrid(n, place, GridDiagonals::Alternating);
  const int32_t middle = (n / 2) * n + n / 2;
  const SurfacePoint source = SurfacePoint::vertex(middle);
  const std::vector<double> radius = fallbackRadii(mesh, source);
  const std::vector<double> graph = dijkstraDistances(mesh, source);
  double worst = 0, graphWorst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t v = j * n + i;
      if (v == middle) continue;
      EXPECT_LE(radius[v], graph[v]) << "vertex " << v;
      EXPECT_GE(radius[v], norm(mesh.position(v) - mesh.position(middle)) * (1 - 1e-12)) << "vertex " << v;
      const double e = exact(i, j);
      worst = std::max(worst, std::abs(radius[v] - e) / e);
      graphWorst = std::max(graphWorst, std::abs(graph[v] - e) / e);
    }
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(worst, graphWorst);  // closer than the edge graph it replaces
}

/// boundaryChords and boundaryEars look only at the loop's rings; these are the scans over every halfedge
/// and face they must agree with (the same entries in the same order).
TEST(BoundaryChordsAndEars, FromTheLoopsRingsAreWhatAScanOfTheWholeMeshFinds) {
  for (const double radius : {3.2, 4.5, 5.6, 6.9}) {
    const TriMesh flat = testing::gridOfCells(15, [radius](int i, int j) {
      return std::hypot(i + 0.5 - 7, j + 0.5 - 7) < radius;
    });
    const std::vector<int32_t>& loop = flat.boundaryLoops().at(0);
    std::vector<int32_t> position(flat.numVertices(), -1);
    for (size_t i = 0; i < loop.size(); ++i) position[loop[i]] = static_cast<int32_t>(i);
    std::vector<std::array<int32_t, 2>> chords;
    for (int32_t h = 0; h < 3 * flat.numFaces(); ++h) {
      const int32_t t = flat.twin(h);
      if (t < 0 || t < h) continue;
      const int32_t a = position[flat.tail(h)], b = position[flat.head(h)];
      if (a >= 0 && b >= 0) chords.push_back({a, b});
    }
    std::vector<std::array<int32_t, 3>> faceEars;
    for (int32_t f = 0; f < flat.numFaces(); ++f) {
      const Triangle& t = flat.triangle(f);
      if (position[t[0]] >= 0 && position[t[1]] >= 0 && position[t[2]] >= 0)
        faceEars.push_back({position[t[0]], position[t[1]], position[t[2]]});
    }
    ASSERT_GE(chords.size(), 4u) << "radius " << radius << ": the staircase must have chords";
    ASSERT_GE(faceEars.size(), 4u) << "radius " << radius << ": the staircase must have ears";
    EXPECT_EQ(boundaryChords(flat, loop), chords) << "radius " << radius;
    const std::vector<BoundaryEar> ears = boundaryEars(flat, loop);
    ASSERT_GE(ears.size(), faceEars.size());
    for (size_t k = 0; k < faceEars.size(); ++k) EXPECT_EQ(ears[k].corners, faceEars[k]) << "radius " << radius;
  }
}

TEST(FallbackRadii, AreWithinTheHeatMethodsAccuracyOfTheGeodesicOnACylinder) {
  // A quarter of a cylinder of radius 2 (angle φ = 0.05 i), height 0.1 j: geodesics are helices, of length
  // √((2 Δφ)² + Δz²).
  const int n = 31;
  auto place = [](int i, int j) { return Vec3{2 * std::cos(0.05 * i), 2 * std::sin(0.05 * i), 0.1 * j}; };
  expectFallbackRadiiNearTheGeodesic(n, place, [&](int i, int j) {
    return std::hypot(2 * 0.05 * (i - n / 2), 0.1 * (j - n / 2));
  });
}

TEST(FallbackRadii, AreWithinTheHeatMethodsAccuracyOfTheGeodesicOnACone) {
  // A cone of half-angle 30° (apex at the origin), slant distance ρ = 1 + 0.05 j, angle φ = 0.04 i around the
  // axis. Unrolled, φ becomes ψ = φ sin 30° and geodesics are straight: √(ρ² + ρ₀² − 2 ρ ρ₀ cos Δψ).
  const int n = 31;
  const double s = std::sin(testing::kPi / 6), c = std::cos(testing::kPi / 6);
  auto place = [&](int i, int j) {
    const double rho = 1 + 0.05 * j, phi = 0.04 * i;
    return Vec3{rho * s * std::cos(phi), rho * s * std::sin(phi), rho * c};
  };
  const double rho0 = 1 + 0.05 * (n / 2);
  expectFallbackRadiiNearTheGeodesic(n, place, [&](int i, int j) {
    const double rho = 1 + 0.05 * j, dpsi = 0.04 * (i - n / 2) * s;
    return std::sqrt(rho * rho + rho0 * rho0 - 2 * rho * rho0 * std::cos(dpsi));
  });
}

}  // namespace
}  // namespace straightest
