// Exact geodesic distances (window propagation) against closed forms: Euclidean on planes (convex, and
// around the reflex corner of an L), the unrolled cone and cylinder; the metric's own laws (symmetry,
// triangle inequality, 1-Lipschitz along edges); exact ≤ straightest and exact ≤ graph on every vertex of
// the samples; back-traced paths as long as the distances they explain.
#include "straightest/geodesics/exact_geodesic.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geodesic_surfaces.hpp"
#include "straightest/base/names.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;
using testing::polylineLength;

ExactGeodesics field(const TriMesh& mesh, const SurfacePoint& source) {
  auto f = exactGeodesics(mesh, source);
  EXPECT_TRUE(f.ok()) << (f.ok() ? "" : f.error().message);
  return std::move(f).value();
}

TEST(ExactGeodesic, PlaneIsEuclideanFromAVertexAnEdgeAndAFacePoint) {
  for (GridPattern pattern : {GridPattern::Regular, GridPattern::UnionJack, GridPattern::Jittered}) {
    const TriMesh mesh = testing::flatGrid(15, pattern);
    for (const SurfacePoint& s : {SurfacePoint::vertex(7 * 15 + 7), SurfacePoint::edge(3 * 40 + 1, 0.3),
                                  SurfacePoint::face(97, {0.2, 0.3, 0.5})}) {
      const ExactGeodesics f = field(mesh, s);
      const Vec3 origin = position(mesh, f.source);
      for (int32_t v = 0; v < mesh.numVertices(); ++v)
        ASSERT_NEAR(f.distances[v], norm(mesh.position(v) - origin), 1e-12) << "vertex " << v;
    }
  }
}

TEST(ExactGeodesic, LShapeBendsAroundTheReflexCorner) {
  const int m = 6;
  const TriMesh mesh = testing::lShape(m);
  const int n = 2 * m + 1;
  const int32_t source = 1 * n + (2 * m - 1);  // (2m − 1, 1): low on the right arm
  const Vec3 s = mesh.position(source), corner{double(m), double(m), 0};
  const ExactGeodesics f = field(mesh, SurfacePoint::vertex(source));
  int bent = 0;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.vertexHalfedge(v) < 0) continue;
    const Vec3 x = mesh.position(v);
    // Hidden from s behind the corner: above it and clockwise of the ray from s through it.
    const bool hidden = x.y > m && cross(corner - s, x - s).z < 0;
    const double expected = hidden ? norm(corner - s) + norm(x - corner) : norm(x - s);
    bent += hidden;
    ASSERT_NEAR(f.distances[v], expected, 1e-12) << "vertex " << v;
  }
  EXPECT_GT(bent, 10);
}

TEST(ExactGeodesic, ConeMatchesItsUnrolling) {
  const testing::Cone c = testing::cone(6, 1.0, 1.0, 8);
  ASSERT_LT(c.totalAngle, 2 * testing::kPi);  // a deficit at the apex
  for (int32_t source : {c.apex, int32_t(37), int32_t(101)}) {
    const ExactGeodesics f = field(c.mesh, SurfacePoint::vertex(source));
    for (int32_t v = 0; v < c.mesh.numVertices(); ++v)
      ASSERT_NEAR(f.distances[v], c.unrolledDistance(source, v), 1e-12) << "source " << source << " vertex " << v;
  }
}

TEST(ExactGeodesic, CylinderMatchesItsUnrolledStripBothWaysAround) {
  const testing::Prism c = testing::prism(24, 9, 1.0, 0.3);
  const int32_t source = 4 * 24 + 5;
  const ExactGeodesics f = field(c.mesh, SurfacePoint::vertex(source));
  for (int32_t v = 0; v < c.mesh.numVertices(); ++v)
    ASSERT_NEAR(f.distances[v], c.unrolledDistance(source, v), 1e-12) << "vertex " << v;
}

TEST(ExactGeodesic, IsAMetricOnTheMountain) {
  const TriMesh mesh = makeSample("mountain").value();
  const int32_t a = 612, b = 1875, c = 1300;
  const ExactGeodesics fa = field(mesh, SurfacePoint::vertex(a)), fb = field(mesh, SurfacePoint::vertex(b)),
                       fc = field(mesh, SurfacePoint::vertex(c));
  EXPECT_NEAR(fa.distances[b], fb.distances[a], 1e-9 * fa.distances[b]);  // symmetric
  EXPECT_NEAR(fa.distances[c], fc.distances[a], 1e-9 * fa.distances[c]);
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    // d(a, v) ≤ d(a, c) + d(c, v), for every v.
    ASSERT_LE(fa.distances[v], fa.distances[c] + fc.distances[v] + 1e-12) << v;
    ASSERT_LE(fb.distances[v], fb.distances[a] + fa.distances[v] + 1e-12) << v;
    // 1-Lipschitz along every edge (an edge is a path on the surface).
    for (int32_t w : mesh.vertexNeighbours(v))
      ASSERT_LE(std::fabs(fa.distances[v] - fa.distances[w]), norm(mesh.position(v) - mesh.position(w)) + 1e-12);
  }
}

TEST(ExactGeodesic, NeverAboveTheStraightestNorTheGraphDistanceOnTheSamples) {
  for (const std::string& name : sampleNames()) {
    const TriMesh mesh = makeSample(name).value();
    const SurfacePoint source = SurfacePoint::vertex(defaultSource(mesh).value());
    const ExactGeodesics f = field(mesh, source);
    const std::vector<double> graph = dijkstraDistances(mesh, source);
    std::vector<SurfacePoint> targets;
    for (int32_t v = 0; v < mesh.numVertices(); ++v)
      if (v != source.index && mesh.vertexHalfedge(v) >= 0) targets.push_back(SurfacePoint::vertex(v));
    const PathBatch batch = traceStraightestPaths(mesh, source, targets, TraceOptions{false}).value();
    int reached = 0;
    for (size_t i = 0; i < targets.size(); ++i) {
      const int32_t v = targets[i].index;
      ASSERT_LE(f.distances[v], graph[v] * (1 + 1e-12)) << name << " vertex " << v;
      ASSERT_GE(f.distances[v], norm(mesh.position(v) - mesh.position(source.index)) * (1 - 1e-12));
      if (batch.status[i] != TraceStatus::Reached) continue;
      ++reached;
      ASSERT_LE(f.distances[v], batch.length[i] * (1 + 1e-12)) << name << " vertex " << v;
    }
    // On a disk most sections reach; on the torus many planes through S cut it in two circles and
    // D lies on the other one (other_component), so only a share of the targets tests the bound there.
    const int least = mesh.boundaryLoops().empty() ? static_cast<int>(targets.size()) / 4
                                                   : static_cast<int>(targets.size()) / 2;
    EXPECT_GT(reached, least) << name;
  }
}

TEST(ExactGeodesic, BackTracedPathsAreAsLongAsTheirDistances) {
  const TriMesh mountain = makeSample("mountain").value();
  const testing::Cone c = testing::cone(6, 1.0, 1.0, 6);
  const TriMesh lshape = testing::lShape(5);
  struct Case {
    const TriMesh* mesh;
    SurfacePoint source;
  };
  for (const Case& k :
       {Case{&mountain, SurfacePoint::vertex(1275)}, Case{&mountain, SurfacePoint::face(900, {0.5, 0.3, 0.2})},
        Case{&c.mesh, SurfacePoint::vertex(20)}, Case{&lshape, SurfacePoint::vertex(13)}}) {
    const TriMesh& mesh = *k.mesh;
    const ExactGeodesics f = field(mesh, k.source);
    for (int32_t v = 0; v < mesh.numVertices(); ++v) {
      if (mesh.vertexHalfedge(v) < 0) continue;  // the L's unreferenced vertices
      auto path = exactShortestPath(mesh, f, v);
      ASSERT_TRUE(path.ok()) << path.error().message;
      const std::vector<Vec3>& p = path.value();
      ASSERT_GE(p.size(), 1u);
      EXPECT_EQ(norm(p.front() - position(mesh, f.source)), 0.0);
      EXPECT_EQ(norm(p.back() - mesh.position(v)), 0.0);
      ASSERT_NEAR(polylineLength(p), f.distances[v], 1e-9 * (1 + f.distances[v])) << "vertex " << v;
    }
  }
}

TEST(ExactGeodesic, PathOnAPlaneIsOneStraightSegment) {
  const TriMesh mesh = testing::flatGrid(12, GridPattern::Jittered);
  const ExactGeodesics f = field(mesh, SurfacePoint::vertex(13));
  const std::vector<Vec3> p = exactShortestPath(mesh, f, 12 * 12 - 2).value();
  ASSERT_GT(p.size(), 3u);  // it crosses edges
  const Vec3 dir = normalized(p.back() - p.front());
  for (const Vec3& x : p) EXPECT_NEAR(norm(cross(x - p.front(), dir)), 0.0, 1e-12);
}

TEST(ExactGeodesic, IsADistanceMethodByName) {
  const TriMesh mesh = makeSample("cap").value();
  EXPECT_EQ(parseDistanceMethod("exact").value(), DistanceMethod::Exact);
  GeodesicDistances distances(mesh);
  const SurfacePoint s = SurfacePoint::vertex(defaultSource(mesh).value());
  EXPECT_EQ(distances.from(s, DistanceMethod::Exact), field(mesh, s).distances);
}

TEST(ExactGeodesic, ReportsProgressAndCancels) {
  const TriMesh mesh = makeHeightField(60);
  double last = -1;
  int calls = 0;
  auto done = exactGeodesics(mesh, SurfacePoint::vertex(0), [&](const char* stage, double fraction) {
    EXPECT_STREQ(stage, "distances");
    EXPECT_GE(fraction, last);
    last = fraction;
    ++calls;
    return true;
  });
  ASSERT_TRUE(done.ok());
  EXPECT_EQ(last, 1.0);
  EXPECT_LE(calls, 102);
  auto cancelled = exactGeodesics(mesh, SurfacePoint::vertex(0), [](const char*, double f) { return f < 0.3; });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

TEST(ExactGeodesic, BadInputIsAnError) {
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  EXPECT_EQ(exactGeodesics(mesh, SurfacePoint::vertex(99)).error().code, ErrorCode::InvalidArgument);
  auto f = exactGeodesics(mesh, SurfacePoint::vertex(3)).value();
  EXPECT_EQ(exactShortestPath(mesh, f, 25).error().code, ErrorCode::InvalidArgument);
  EXPECT_EQ(exactShortestPath(mesh, f, -1).error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace straightest
