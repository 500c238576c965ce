// Numerical robustness: badly conditioned inputs give the well-conditioned answer (the tolerances are
// relative to the mesh's own scale) or a clear status, never a crash, hang or silent wrong number.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "straightest/geodesic_distance.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"
#include "straightest/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

TriMesh scaled(const TriMesh& mesh, double s) {
  std::vector<Vec3> p;
  for (const Vec3& x : mesh.positions()) p.push_back(x * s);
  return testing::buildOrFail(p, mesh.triangles());
}

TEST(Robustness, PathsAndParameterizationAreScaleInvariant) {
  const TriMesh base = makeSample("face").value();
  const int32_t source = defaultSource(base).value();
  const PathBatch reference = traceStraightestPaths(base, SurfacePoint::vertex(source), boundaryTargets(base), TraceOptions{false}).value();
  ParamOptions options;
  const Parameterization referenceParam = parameterize(base, options).value();
  for (double s : {1e-6, 1e6}) {
    const TriMesh mesh = scaled(base, s);
    EXPECT_EQ(defaultSource(mesh).value(), source);
    const PathBatch batch = traceStraightestPaths(mesh, SurfacePoint::vertex(source), boundaryTargets(mesh), TraceOptions{false}).value();
    for (size_t i = 0; i < batch.status.size(); ++i) {
      EXPECT_EQ(batch.status[i], reference.status[i]) << "scale " << s << " path " << i;
      EXPECT_NEAR(batch.length[i] / s, reference.length[i], 1e-9 * reference.length[i]) << "scale " << s;
      EXPECT_EQ(batch.facesCrossed[i], reference.facesCrossed[i]);
    }
    const Parameterization p = parameterize(mesh, options).value();
    EXPECT_NEAR(p.metrics.l2, referenceParam.metrics.l2, 1e-9) << "scale " << s;
    EXPECT_NEAR(p.metrics.linf, referenceParam.metrics.linf, 1e-7) << "scale " << s;
    for (size_t v = 0; v < p.uv.size(); v += 17) {
      EXPECT_NEAR(p.uv[v][0], referenceParam.uv[v][0], 1e-9);
      EXPECT_NEAR(p.uv[v][1], referenceParam.uv[v][1], 1e-9);
    }
  }
}

TEST(Robustness, AlmostFlatPatchBehavesLikeAFlatOne) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-1e-10, 1e-10);
  const TriMesh mesh = testing::grid(21, testing::GridPattern::Jittered, [&](double x, double y) {
    return Vec3{x, y, noise(rng)};
  });
  const int32_t source = defaultSource(mesh).value();
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(source));
  EXPECT_NEAR(std::abs(tracer.base().normal.z), 1.0, 1e-12);
  for (const SurfacePoint& t : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(t);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const double euclid = norm(position(mesh, t) - mesh.position(source));
    EXPECT_NEAR(path.length, euclid, 1e-8 * euclid);
  }
  const Parameterization p = parameterize(mesh, {}).value();
  EXPECT_NEAR(p.metrics.l2, 1.0, 1e-6);
  EXPECT_TRUE(p.metrics.bijective);
}

TEST(Robustness, SliverTrianglesDoNotDerailTheWalk) {
  // A flat strip whose middle row of vertices sits 1e-9 above the line y = 1: the triangles along it
  // have angles ~1e-9. Paths across must still come out Euclidean (the plane is exactly the x-y plane).
  const int n = 11;
  const TriMesh mesh = testing::grid(n, testing::GridPattern::Regular, [&](double x, double y) {
    return Vec3{x, y == 1 ? 1 + 1e-9 * x : y, 0};
  });
  EXPECT_EQ(mesh.summary().degenerateFaces, 0);
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(5 * n + 5));
  for (const SurfacePoint& t : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(t);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const double euclid = norm(position(mesh, t) - mesh.position(5 * n + 5));
    EXPECT_NEAR(path.length, euclid, 1e-9 * euclid);
  }
}

TEST(Robustness, NearDuplicateVerticesAreKeptAndTracesTerminate) {
  // Two vertices 1e-13 apart (not welded: the file's vertex order is kept), each used by faces.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0.5 + 1e-13, 0.5, 0}};
  std::vector<Triangle> t{{0, 1, 5}, {1, 2, 5}, {2, 3, 4}, {3, 0, 4}, {0, 5, 4}, {2, 4, 5}};
  const TriMesh mesh = testing::buildOrFail(p, t);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 1);
  EXPECT_EQ(mesh.summary().degenerateFaces, 2);  // the two slivers between the twins
  for (int32_t s : {4, 5}) {
    StraightestPathTracer tracer(mesh, SurfacePoint::vertex(s));
    for (int32_t v = 0; v < 4; ++v) {
      const StraightestPath& path = tracer.trace(SurfacePoint::vertex(v));
      ASSERT_LT(static_cast<int>(path.status), kTraceStatusCount);
      if (path.status == TraceStatus::Reached) {
        EXPECT_NEAR(path.length, norm(p[v] - p[s]), 1e-9);
      }
    }
  }
}

TEST(Robustness, AlmostClosedCapReportsTheBaseNormalFallbackAndStaysBijectiveOnACircle) {
  // A spherical cap of polar angle π − 0.05: a sphere with a small hole at the bottom. Seen from the
  // pole, the virtual faces to the tiny rim are slivers whose unit normals point every way around:
  // their mean nearly cancels, so the base normal falls back to the area-weighted normal (reported).
  const TriMesh mesh = makeSphericalCap(1.0, testing::kPi - 0.05, 24);
  const BasePlane base = basePlane(mesh, SurfacePoint::vertex(0));
  EXPECT_TRUE(base.fallback);
  EXPECT_NE(base.note.find("cancel"), std::string::npos) << base.note;
  EXPECT_NEAR(base.normal.z, 1.0, 1e-9);  // the pole's own normal
  const PathBatch batch = traceStraightestPaths(mesh, SurfacePoint::vertex(0), boundaryTargets(mesh), TraceOptions{false}).value();
  for (TraceStatus s : batch.status) EXPECT_LT(static_cast<int>(s), kTraceStatusCount);
  ParamOptions o;
  o.boundary = BoundaryKind::Circle;
  const Parameterization p = parameterize(mesh, o).value();
  EXPECT_TRUE(p.metrics.bijective);  // Tutte: a convex boundary and convex weights never fold
  o.boundary = BoundaryKind::Measured;
  auto measured = parameterize(mesh, o);  // may be poor, but it is a result or a clear error
  if (measured) {
    EXPECT_EQ(std::isfinite(measured.value().metrics.l2), measured.value().metrics.bijective);
  } else {
    EXPECT_FALSE(measured.error().message.empty());
  }
}

TEST(Robustness, BaseNormalFacesTheSurfaceSideEvenNextToTheHoleOfANearlyClosedMesh) {
  const TriMesh sphere = testing::icosphere(2);
  std::vector<Triangle> kept;
  for (const Triangle& t : sphere.triangles())
    if (t[0] != 0 && t[1] != 0 && t[2] != 0) kept.push_back(t);
  const TriMesh mesh = testing::buildOrFail(sphere.positions(), kept);  // vertex 0 is now unreferenced
  for (int32_t v = 1; v < mesh.numVertices(); ++v) {
    if (mesh.isBoundaryVertex(v)) continue;
    const BasePlane base = basePlane(mesh, SurfacePoint::vertex(v));
    EXPECT_GT(dot(base.normal, mesh.position(v)), 0) << "vertex " << v << ": base plane faces into the sphere";
  }
}

}  // namespace
}  // namespace straightest
