// Unit tests for the bugs fuzzing found (tests/fuzz/regressions/ keeps the raw inputs; these tests
// pin each one down on a small, readable mesh so it stays fixed in every build, native and WASM).
#include <cmath>

#include <gtest/gtest.h>

#include "straightest/boundary_map.hpp"
#include "straightest/mesh_io.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::buildOrFail;
using testing::flatGrid;
using testing::grid;
using testing::GridPattern;

TEST(FuzzFindings, ObjStatementsOtherThanVAndFNeverReachTinyobjloader) {
  // tinyobjloader converted the joint id 3e9 of a "vw" line to int (undefined behaviour).
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 3e9 1\nvt 0 1e-99999\nf 1 2 3\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(FuzzFindings, ObjKeywordsAreDelimitedBySpaceOrTabOnly) {
  // A vertical tab before or after "v"/"f" does not make a statement (as in tinyobjloader); our reader
  // and tinyobjloader read the same lines.
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n\v\vf 2 4 3\nv\v5 5 5\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numVertices(), 4);
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(FuzzFindings, CoordinatesWhoseSquaredAreasOverflowAreRefused) {
  // 1e100 gave faces of infinite area (|e1 × e2|² overflows); 1e40 is fine.
  const std::vector<Triangle> t{{0, 1, 2}};
  auto huge = TriMesh::build({{0, 0, 0}, {1e100, 0, 0}, {0, 1e100, 0}}, t);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().code, ErrorCode::NonFinite);
  auto large = TriMesh::build({{0, 0, 0}, {1e40, 0, 0}, {0, 1e40, 0}}, t);
  ASSERT_TRUE(large.ok()) << large.error().message;
  EXPECT_TRUE(std::isfinite(large.value().faceArea(0)));
  EXPECT_NEAR(large.value().faceArea(0) / 0.5e80, 1.0, 1e-12);
}

TEST(FuzzFindings, TargetNextToAVertexOnThePathIsReached) {
  // Flat 10 × 10 grid. From S = (2, 2) toward v = (6, 4) the section passes exactly through v; a target
  // on the edge v → (6, 5) at t = 1e-10 puts v on its cutting plane, yet none of the faces the walk
  // uses at v holds it. It must be reached, with the straight-line length.
  const TriMesh mesh = flatGrid(10, GridPattern::Regular);
  const int32_t s = 2 * 10 + 2, v = 4 * 10 + 6, up = 5 * 10 + 6;
  int32_t h = -1;
  for (int32_t k = 0; k < 3 * mesh.numFaces(); ++k)
    if (mesh.tail(k) == v && mesh.head(k) == up) h = k;
  ASSERT_GE(h, 0);
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(s));
  for (double t : {1e-10, 1e-12, 1e-7}) {
    const SurfacePoint target = SurfacePoint::edge(h, t);
    const StraightestPath& path = tracer.trace(target);
    ASSERT_EQ(path.status, TraceStatus::Reached) << "t = " << t << ": " << traceStatusName(path.status);
    // The walk goes through v, then the last tiny step v → D: longer than |SD| by less than 2 |vD|.
    EXPECT_NEAR(path.length, norm(position(mesh, target) - mesh.position(s)), 2 * t + 1e-12) << "t = " << t;
    EXPECT_EQ(path.points.back().kind, SurfacePoint::Kind::Edge);
  }
}

TEST(FuzzFindings, SourceOnAnEdgeWithThePlaneAlmostAlongTheEdgeLeavesThroughAFace) {
  // Flat 10 × 10 grids, rotated and moved far from the origin; S at the midpoint of a diagonal edge,
  // D at t ≤ 1e-7 on an edge of the grid vertex one more cell along the diagonal, so the plane crosses
  // the source edge at S at an angle below ~5e-8. The computed crossing of that edge landed up to ~1e-6
  // from S (rounding at coordinates ~1000), was taken as the first step, and led the walk back through
  // the edge to S (returned_to_source; hit_boundary in another run). Each target must be reached along
  // the straight segment.
  int checked = 0, n = 10;
  for (double angle : {0.0, 0.3, 1.1, 2.5})
    for (const Vec3& offset : {Vec3{1000, -500, 250}, Vec3{-3000, 7000, 1}}) {
      const double c = std::cos(angle), s = std::sin(angle);
      const TriMesh mesh = grid(n, GridPattern::Regular,
                                [&](double x, double y) { return offset + Vec3{c * x - s * y, s * x + c * y, 0}; });
      auto find = [&](int32_t a, int32_t b) {
        for (int32_t k = 0; k < 3 * mesh.numFaces(); ++k)
          if (mesh.tail(k) == a && mesh.head(k) == b) return k;
        return -1;
      };
      for (int i = 2; i <= 5; ++i)
        for (int j = 2; j <= 5; ++j) {
          // The diagonal of square (i, j), in whichever direction the grid splits it, and the vertex one
          // more cell along it (grid vertex (i, j) has index j n + i).
          int32_t a = j * n + i, b = a + n + 1, far = b + n + 1, di = 1;
          if (find(a, b) < 0) a = j * n + i + 1, b = a + n - 1, far = b + n - 1, di = -1;
          const int32_t h = find(a, b);
          ASSERT_GE(h, 0) << "no diagonal edge in square " << i << ", " << j;
          const Vec3 S = (mesh.position(a) + mesh.position(b)) * 0.5;
          StraightestPathTracer tracer(mesh, SurfacePoint::edge(h, 0.5));
          for (double t : {1e-7, 3e-8, 1e-9})
            for (int32_t next : {far - di, far - n}) {  // the edges from far back toward the diagonal's side
              const int32_t e = find(far, next);
              ASSERT_GE(e, 0);
              const SurfacePoint target = SurfacePoint::edge(e, t);
              const StraightestPath& path = tracer.trace(target);
              ++checked;
              ASSERT_EQ(path.status, TraceStatus::Reached)
                  << "angle " << angle << ", square " << i << ", " << j << ", t " << t << ": "
                  << traceStatusName(path.status);
              EXPECT_NEAR(path.length, norm(position(mesh, target) - S), 1e-9);
            }
        }
    }
  EXPECT_EQ(checked, 4 * 2 * 16 * 3 * 2);
}

TEST(FuzzFindings, DestinationAlmostAlongTheBaseNormalHasNoPlane) {
  // Below a sine of 1e-8 the plane's normal is dominated by rounding (the fuzzer saw D 8e-7 off it).
  BasePlane base;
  base.origin = {0, 0, 0};
  base.normal = {0, 0, 1};
  EXPECT_FALSE(cuttingPlane(base, {1e-9, 0, 1}).has_value());
  const auto plane = cuttingPlane(base, {1e-7, 0, 1});
  ASSERT_TRUE(plane.has_value());
  EXPECT_LE(std::abs(dot(plane->normal, Vec3{1e-7, 0, 1})), 1e-15);
}

/// A flat 9 × 9 grid (8 × 8 cells) without the cells listed, as (column, row) of their lower-left corner.
TriMesh gridWithout(const std::vector<std::array<int, 2>>& removed) {
  const int n = 9;
  std::vector<Vec3> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p.push_back({double(i), double(j), 0});
  std::vector<Triangle> t;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      bool skip = false;
      for (const auto& c : removed) skip |= c[0] == i && c[1] == j;
      if (skip) continue;
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      t.push_back({a, b, d});
      t.push_back({a, d, c});
    }
  return buildOrFail(std::move(p), std::move(t));
}

TEST(FuzzFindings, MeasuredBoundaryWithAnEdgePointingAtTheSourceIsBijective) {
  // Removing cell (7, 3) puts the boundary edge (8, 4) → (7, 4) on the ray from S = (4, 4): both ends
  // had the same polar angle and landed on one point of the hull, collapsing a triangle.
  const TriMesh mesh = gridWithout({{7, 3}});
  ParamOptions options;
  options.source = SurfacePoint::vertex(4 * 9 + 4);
  for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform}) {
    options.weights = w;
    auto p = parameterize(mesh, options);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_TRUE(p.value().metrics.bijective) << weightKindName(w) << ": " << p.value().metrics.flipped << " flipped, "
                                             << p.value().metrics.degenerate << " degenerate";
  }
}

TEST(FuzzFindings, ConvexifyBulgesAChordBetweenTwoHullCornersWithAPointBetween) {
  // A, B, C on one hull edge (A and C corners), chord A–C: triangle ABC would collapse unless B is lifted.
  std::vector<Vec2> pts{{-1, -1}, {0, -1}, {1, -1}, {1, 1}, {-1, 1}};
  ASSERT_EQ(convexify(pts, {{0, 2}}), 0);
  EXPECT_LT(pts[1][1], -1 - 1e-3);  // lifted outward (below the edge y = −1)
  EXPECT_DOUBLE_EQ(pts[0][1], -1);
  EXPECT_DOUBLE_EQ(pts[2][1], -1);
}

TEST(FuzzFindings, ConvexifyTreatsARoundingMadeHullCornerAsStraight) {
  // B sticks out of the edge AC by 1e-13 (a corner turning by a sine of ~1e-13): the hull must still
  // see one edge A–C and lift B, else the chord A–C keeps a collapsed triangle.
  std::vector<Vec2> pts{{-1, -1}, {0, -1 - 1e-13}, {1, -1}, {1, 1}, {-1, 1}};
  ASSERT_GE(convexify(pts, {{0, 2}}), 0);
  EXPECT_LT(pts[1][1], -1 - 1e-3);
}

TEST(FuzzFindings, ASourceWithinSnappingDistanceOfTheBoundaryIsRefused) {
  // The tracer moves a source within 1e-6 of a vertex onto it; a point 2e-8 from a boundary vertex
  // became a boundary source with radius 0. parameterize must refuse it like a boundary vertex.
  const TriMesh mesh = flatGrid(5, GridPattern::Regular);
  int32_t h = -1;  // an interior halfedge leaving boundary vertex 1 = (1, 0) toward (1, 1)
  for (int32_t k = 0; k < 3 * mesh.numFaces(); ++k)
    if (mesh.tail(k) == 1 && mesh.head(k) == 6) h = k;
  ASSERT_GE(h, 0);
  ParamOptions options;
  options.source = SurfacePoint::edge(h, 2e-8);
  auto p = parameterize(mesh, options);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(p.error().message.find("on the boundary"), std::string::npos) << p.error().message;
  options.source = SurfacePoint::edge(h, 0.5);  // well inside: fine
  EXPECT_TRUE(parameterize(mesh, options).ok());
}

}  // namespace
}  // namespace straightest
