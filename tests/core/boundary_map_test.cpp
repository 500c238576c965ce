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
  ParamOptions options;
  options.autoSource = false;
  options.source = SurfacePoint::vertex(4 * 9 + 4);
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
