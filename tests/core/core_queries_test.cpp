// Small queries the page asks the core instead of computing them itself: vertex normals, the
// resolved source, distances by method (heat factored once), and the exception → error mapping.
#include <new>
#include <stdexcept>

#include <gtest/gtest.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/base_plane.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

TEST(VertexNormals, AreTheAreaWeightedNormalAtEveryVertex) {
  const TriMesh mesh = makeSample("saddle").value();
  const std::vector<Vec3> normals = vertexNormals(mesh);
  ASSERT_EQ(normals.size(), static_cast<size_t>(mesh.numVertices()));
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    EXPECT_NEAR(norm(normals[v]), 1, 1e-12);
    EXPECT_LT(norm(normals[v] - areaWeightedNormal(mesh, SurfacePoint::vertex(v))), 1e-12) << v;
  }
  for (const Vec3& n : vertexNormals(testing::flatGrid(5, testing::GridPattern::UnionJack)))
    EXPECT_EQ(std::abs(n.z), 1.0);
}

TEST(ResolveSource, AutoIsTheDefaultSourceAndAGivenPointIsValidated) {
  const TriMesh mesh = makeSample("cap").value();
  const SurfacePoint autoSource = resolveSource(mesh, std::nullopt).value();
  EXPECT_EQ(autoSource.kind, SurfacePoint::Kind::Vertex);
  EXPECT_EQ(autoSource.index, defaultSource(mesh).value());
  EXPECT_EQ(resolveSource(mesh, SurfacePoint::vertex(7)).value().index, 7);
  EXPECT_FALSE(resolveSource(mesh, SurfacePoint::vertex(mesh.numVertices())).ok());
  EXPECT_FALSE(resolveSource(mesh, SurfacePoint::face(0, {1, 1, 1})).ok());
}

TEST(GeodesicDistances, DispatchesByMethodAndReusesOneHeatFactorization) {
  const TriMesh mesh = makeSample("mountain").value();
  const SurfacePoint a = SurfacePoint::vertex(defaultSource(mesh).value()), b = SurfacePoint::vertex(0);
  GeodesicDistances distances(mesh);
  const HeatMethod heat(mesh);
  EXPECT_EQ(distances.from(a, DistanceMethod::Heat), heat.distances(a));
  EXPECT_EQ(distances.from(b, DistanceMethod::Heat), heat.distances(b));
  EXPECT_EQ(distances.from(a, DistanceMethod::Dijkstra), dijkstraDistances(mesh, a));
  EXPECT_EQ(parseDistanceMethod("magic").error().message,
            "unknown distance method 'magic' (use heat, dijkstra or exact)");
}

TEST(ErrorFromException, AllocationFailureIsTooLargeAndAnythingElseInternal) {
  const auto tooLarge = guarded([]() -> Expected<int> { throw std::bad_alloc(); });
  ASSERT_FALSE(tooLarge.ok());
  EXPECT_EQ(tooLarge.error().code, ErrorCode::TooLarge);
  EXPECT_NE(tooLarge.error().message.find("too large for the available memory"), std::string::npos);
  const auto bug = guarded([]() -> Expected<int> { throw std::logic_error("broken invariant"); });
  EXPECT_EQ(bug.error().code, ErrorCode::Internal);
  EXPECT_EQ(bug.error().message, "internal error: broken invariant");
  EXPECT_STREQ(errorCodeName(ErrorCode::Internal), "internal");
  EXPECT_EQ(errorCodeNames().back(), "internal");
  EXPECT_EQ(guarded([]() -> Expected<int> { return 4; }).value(), 4);
}

}  // namespace
}  // namespace straightest
