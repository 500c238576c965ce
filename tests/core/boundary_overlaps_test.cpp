// Boundary self-overlap: a strip wound around a centre keeps every triangle positive, but once it
// winds more than a full turn its ends cross the earlier turn, so the map is not injective.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/param/boundary_overlaps.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

/// A flat strip of `cells` squares (vertices (i, j), i ≤ cells, j ≤ 1) and its uv wound clockwise
/// around the origin through `turns` full turns: θ = −2π turns i / cells, r = 1 + 0.3 j + 0.1 θ/2π
/// (radius growing by 0.1 per turn, less than the strip's width 0.3). Clockwise in θ keeps the
/// triangles counter-clockwise in uv.
struct WoundStrip {
  TriMesh mesh;
  std::vector<Vec2> uv;
};
WoundStrip woundStrip(int cells, double turns) {
  std::vector<Vec3> p;
  std::vector<Triangle> t;
  std::vector<Vec2> uv;
  for (int i = 0; i <= cells; ++i)
    for (int j = 0; j <= 1; ++j) {
      p.push_back({0.1 * i, 0.3 * j, 0});
      const double theta = -2 * kPi * turns * i / cells;
      const double r = 1 + 0.3 * j + 0.1 * std::abs(theta) / (2 * kPi);
      uv.push_back({r * std::cos(theta), r * std::sin(theta)});
    }
  for (int i = 0; i < cells; ++i) {
    const int a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
    t.push_back({a, b, c});
    t.push_back({a, c, d});
  }
  return {testing::buildOrFail(p, t), uv};
}

TEST(BoundaryOverlaps, AConvexMapHasNone) {
  const TriMesh mesh = testing::flatGrid(6, testing::GridPattern::Jittered);
  std::vector<Vec2> uv;
  for (const Vec3& q : mesh.positions()) uv.push_back({q.x, q.y});
  EXPECT_EQ(boundaryOverlaps(mesh, uv), 0);
  EXPECT_EQ(textureStretch(mesh, uv).overlaps, 0);
}

TEST(BoundaryOverlaps, AStripWoundLessThanATurnHasNone) {
  const WoundStrip s = woundStrip(120, 0.75);
  const StretchMetrics m = textureStretch(s.mesh, s.uv);
  EXPECT_EQ(m.flipped, 0);
  EXPECT_EQ(m.degenerate, 0);
  EXPECT_EQ(m.overlaps, 0);
  EXPECT_TRUE(m.bijective);
}

TEST(BoundaryOverlaps, AStripWoundPastATurnOverlapsItselfAndIsNotBijective) {
  const WoundStrip s = woundStrip(240, 1.5);
  const StretchMetrics m = textureStretch(s.mesh, s.uv);
  EXPECT_EQ(m.flipped, 0);  // every triangle is positive ...
  EXPECT_EQ(m.degenerate, 0);
  // ... but each end cap crosses the other turn's side: the start cap the second turn's inner side,
  // the end cap the first turn's outer side.
  EXPECT_EQ(m.overlaps, 2);
  EXPECT_EQ(boundaryOverlaps(s.mesh, s.uv), 2);
  EXPECT_FALSE(m.bijective);
  EXPECT_TRUE(std::isinf(m.l2));
}

TEST(BoundaryOverlaps, TouchingWithoutSharingAVertexCounts) {
  // A 3 × 3 grid over [0, 2]²: the middle of the bottom side moved onto the top side touches it.
  const TriMesh mesh = testing::flatGrid(3, testing::GridPattern::Regular);
  std::vector<Vec2> uv;
  int32_t bottomMiddle = -1;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const Vec3& q = mesh.position(v);
    uv.push_back({q.x, q.y});
    if (q.x == 1 && q.y == 0) bottomMiddle = v;
  }
  ASSERT_GE(bottomMiddle, 0);
  EXPECT_EQ(boundaryOverlaps(mesh, uv), 0);
  uv[bottomMiddle] = {1.5, 2};
  EXPECT_GT(boundaryOverlaps(mesh, uv), 0);
}

}  // namespace
}  // namespace straightest
