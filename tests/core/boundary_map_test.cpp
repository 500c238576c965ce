// The boundary polygon of a map: convexify lifts the points a chord would collapse, and the measured
// boundary stays bijective where a boundary edge points at the source.
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/boundary_map.hpp"
#include "straightest/parameterize.hpp"
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

}  // namespace
}  // namespace straightest
