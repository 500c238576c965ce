// Untangling (private: core/src/untangle.hpp): a map folded inside a fixed convex boundary comes out
// with every face positive and the boundary where it was.
#include <random>

#include <gtest/gtest.h>

#include "../../core/param/src/free/untangle.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

std::vector<uint8_t> boundaryFixed(const TriMesh& mesh) {
  std::vector<uint8_t> fixed(mesh.numVertices());
  for (int32_t v = 0; v < mesh.numVertices(); ++v) fixed[v] = mesh.isBoundaryVertex(v);
  return fixed;
}

// No deadline: what the untangling achieves must not depend on how fast the machine (or a sanitizer
// build) runs it; its rounds and iterations are bounded by themselves.
Expected<UntangleResult> run(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  return untangle(mesh, uv, boundaryFixed(mesh), std::chrono::steady_clock::time_point::max(), {});
}

TEST(Untangle, AScrambledInteriorBecomesInjectiveAndTheBoundaryStays) {
  const TriMesh mesh = testing::flatGrid(10, testing::GridPattern::UnionJack);
  std::vector<Vec2> uv;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> anywhere(0, 9);
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const Vec3& p = mesh.position(v);
    uv.push_back(mesh.isBoundaryVertex(v) ? Vec2{p.x, p.y} : Vec2{anywhere(rng), anywhere(rng)});
  }
  ASSERT_GT(textureStretch(mesh, uv).flipped, 10);
  auto r = run(mesh, uv);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().injective);
  EXPECT_TRUE(allFacesPositive(mesh, r.value().uv, kUntangledArea));
  EXPECT_TRUE(textureStretch(mesh, r.value().uv).bijective);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (mesh.isBoundaryVertex(v)) {
      EXPECT_EQ(r.value().uv[v], uv[v]);
    }
}

TEST(Untangle, EveryInteriorVertexOnOnePointIsSpreadOut) {
  // The limit of underflow: the whole interior collapsed to the centre (every interior face has zero area).
  const TriMesh mesh = testing::almostFlatGrid(8, 0.5);
  std::vector<Vec2> uv;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const Vec3& p = mesh.position(v);
    uv.push_back(mesh.isBoundaryVertex(v) ? Vec2{p.x, p.y} : Vec2{3.5, 3.5});
  }
  auto r = run(mesh, uv);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().injective);
  EXPECT_TRUE(textureStretch(mesh, r.value().uv).bijective);
}

TEST(Untangle, AScrambledLongFingerIsUntangledAlongItsWholeLength) {
  // Like an animal's leg in a patch: a long tube folded all along, whose map must open all the way to
  // the tip with the boundary held.
  const TriMesh mesh = testing::finger(48);
  ParamOptions o;
  o.boundary = BoundaryKind::Circle;
  auto start = parameterize(mesh, o);
  ASSERT_TRUE(start);
  std::vector<Vec2> uv = start.value().uv;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> anywhere(-0.7, 0.7);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (!mesh.isBoundaryVertex(v)) uv[v] = {anywhere(rng), anywhere(rng)};
  ASSERT_GT(textureStretch(mesh, uv).flipped, mesh.numFaces() / 4);
  auto r = run(mesh, uv);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().injective);
  EXPECT_TRUE(textureStretch(mesh, r.value().uv).bijective);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (mesh.isBoundaryVertex(v)) {
      EXPECT_EQ(r.value().uv[v], uv[v]);
    }
}

TEST(Untangle, AnInjectiveMapIsAlreadyDone) {
  const TriMesh mesh = testing::flatGrid(6, testing::GridPattern::Regular);
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.positions()) uv.push_back({p.x, p.y});
  auto r = run(mesh, uv);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r.value().injective);
}

TEST(Untangle, CancellingStopsWithCancelled) {
  const TriMesh mesh = testing::flatGrid(10, testing::GridPattern::Regular);
  std::vector<Vec2> uv;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    const Vec3& p = mesh.position(v);
    uv.push_back(mesh.isBoundaryVertex(v) ? Vec2{p.x, p.y} : Vec2{1, 1});
  }
  auto r = untangle(mesh, uv, boundaryFixed(mesh), std::chrono::steady_clock::now() + std::chrono::seconds(60),
                    [](const char*, double) { return false; });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
}

}  // namespace
}  // namespace straightest
