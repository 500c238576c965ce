// Texture stretch (Sander et al.): 1 for an isometry or a uniform scale, the singular values of the
// inverse Jacobian for a shear, infinite (and counted) for flipped and degenerate triangles.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/param/texture_stretch.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;

/// The flat mesh's own x, y as uv, scaled and sheared (u = scale (x + shear y), v = scale y).
std::vector<Vec2> planarUV(const TriMesh& mesh, double scale = 1, double shear = 0) {
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.positions()) uv.push_back({scale * (p.x + shear * p.y), scale * p.y});
  return uv;
}

TEST(TextureStretch, IsometryScoresOne) {
  const TriMesh mesh = testing::flatGrid(8, GridPattern::Jittered);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh));
  EXPECT_NEAR(m.l2, 1, 1e-12);
  EXPECT_NEAR(m.linf, 1, 1e-12);
  EXPECT_NEAR(m.angleDistortionMax, 1, 1e-9);
  EXPECT_NEAR(m.areaDistortionMax, 1, 1e-9);
  EXPECT_TRUE(m.bijective);
}

TEST(TextureStretch, UniformScaleScoresOne) {
  const TriMesh mesh = testing::flatGrid(8, GridPattern::UnionJack);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh, 0.01));
  EXPECT_NEAR(m.l2, 1, 1e-12);
  EXPECT_NEAR(m.linf, 1, 1e-12);
}

TEST(TextureStretch, ShearHasTheSingularValuesOfItsInverse) {
  // uv = (x + k y, y): the inverse Jacobian has S_s = (1, 0, 0), S_t = (−k, 1, 0); area is preserved.
  const double k = 0.5;
  const TriMesh mesh = testing::flatGrid(6, GridPattern::Regular);
  const StretchMetrics m = textureStretch(mesh, planarUV(mesh, 1, k));
  const double a = 1, b = -k, c = 1 + k * k;
  EXPECT_NEAR(m.l2, std::sqrt((a + c) / 2), 1e-12);
  EXPECT_NEAR(m.linf, std::sqrt(((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)) / 2), 1e-12);
  EXPECT_NEAR(m.areaDistortionMax, 1, 1e-9);
  EXPECT_GT(m.angleDistortionMean, 1.5);
}

TEST(TextureStretch, FlippedTriangleMakesStretchInfiniteAndIsCounted) {
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  std::vector<Vec2> uv = planarUV(mesh);
  uv[12] = {uv[12][0] + 1.6, uv[12][1] + 1.6};  // the centre vertex jumps over its neighbours
  const StretchMetrics m = textureStretch(mesh, uv);
  EXPECT_GT(m.flipped, 0);
  EXPECT_FALSE(m.bijective);
  EXPECT_TRUE(std::isinf(m.l2));
  EXPECT_TRUE(std::isinf(m.linf));
}

TEST(TextureStretch, DegenerateTriangleIsCountedAndNotBijective) {
  const TriMesh mesh = testing::flatGrid(3, GridPattern::Regular);
  std::vector<Vec2> uv = planarUV(mesh);
  uv[4] = {0.5, 0.0};  // the centre lands on the edge (0, 1): triangle (0, 1, 4) has zero area
  const StretchMetrics m = textureStretch(mesh, uv);
  EXPECT_GE(m.degenerate, 1);
  EXPECT_TRUE(std::isinf(m.l2));
}

}  // namespace
}  // namespace straightest
