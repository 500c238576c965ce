// The per-face pieces of the free-boundary refinement (private: core/src/symmetric_dirichlet.hpp):
// the energy is 4 for a rotation and infinite for a flip, its derivative is what SLIM's weights
// reproduce, and the flip-free step stops exactly where a face would flip.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "../../core/param/src/free/symmetric_dirichlet.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

Mat2 rotation(double angle) { return {std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle)}; }

TEST(SymmetricDirichlet, IsFourForARotationAndInfiniteForAFlipOrACollapse) {
  EXPECT_DOUBLE_EQ(symmetricDirichlet(rotation(0.7)), 4.0);
  EXPECT_DOUBLE_EQ(symmetricDirichlet({2, 0, 0, 0.5}), 4.25 * 2);  // (4 + 1/4)(1 + 1)
  EXPECT_TRUE(std::isinf(symmetricDirichlet({1, 0, 0, -1})));
  EXPECT_TRUE(std::isinf(symmetricDirichlet({1, 2, 0.5, 1})));  // det 0
}

TEST(SymmetricDirichlet, ItsGradientMatchesFiniteDifferences) {
  const Mat2 j{1.3, 0.4, -0.2, 0.7};
  const Mat2 g = symmetricDirichletGradient(j);
  const double h = 1e-6;
  const double numeric[4] = {
      (symmetricDirichlet({j.a + h, j.b, j.c, j.d}) - symmetricDirichlet({j.a - h, j.b, j.c, j.d})) / (2 * h),
      (symmetricDirichlet({j.a, j.b + h, j.c, j.d}) - symmetricDirichlet({j.a, j.b - h, j.c, j.d})) / (2 * h),
      (symmetricDirichlet({j.a, j.b, j.c + h, j.d}) - symmetricDirichlet({j.a, j.b, j.c - h, j.d})) / (2 * h),
      (symmetricDirichlet({j.a, j.b, j.c, j.d + h}) - symmetricDirichlet({j.a, j.b, j.c, j.d - h})) / (2 * h)};
  EXPECT_NEAR(g.a, numeric[0], 1e-6);
  EXPECT_NEAR(g.b, numeric[1], 1e-6);
  EXPECT_NEAR(g.c, numeric[2], 1e-6);
  EXPECT_NEAR(g.d, numeric[3], 1e-6);
}

TEST(SymmetricDirichlet, SlimsProxyHasTheEnergysGradientAndARotationTarget) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> entry(-2, 2);
  for (int k = 0; k < 200; ++k) {
    Mat2 j{entry(rng), entry(rng), entry(rng), entry(rng)};
    if (j.det() < 0) std::swap(j.a, j.b), std::swap(j.c, j.d);  // swap columns: det changes sign
    if (!(j.det() > 1e-3)) continue;
    Mat2 m, r;
    slimLocalStep(j, m, r);
    EXPECT_NEAR(r.det(), 1.0, 1e-12);
    EXPECT_NEAR(r.a * r.b + r.c * r.d, 0.0, 1e-12);
    // Rᵀ J is symmetric (R is the polar factor of J).
    EXPECT_NEAR(r.a * j.b + r.c * j.d, r.b * j.a + r.d * j.c, 1e-9 * (1 + j.squaredNorm()));
    // M is symmetric positive definite and 2 (J − R) M = ∂E/∂J.
    EXPECT_DOUBLE_EQ(m.b, m.c);
    EXPECT_GT(m.a, 0);
    EXPECT_GT(m.det(), 0);
    const Mat2 d{j.a - r.a, j.b - r.b, j.c - r.c, j.d - r.d};
    const Mat2 proxy{2 * (d.a * m.a + d.b * m.c), 2 * (d.a * m.b + d.b * m.d), 2 * (d.c * m.a + d.d * m.c),
                     2 * (d.c * m.b + d.d * m.d)};
    const Mat2 g = symmetricDirichletGradient(j);
    const double scale = 1 + std::sqrt(g.squaredNorm());
    EXPECT_NEAR(proxy.a, g.a, 1e-9 * scale);
    EXPECT_NEAR(proxy.b, g.b, 1e-9 * scale);
    EXPECT_NEAR(proxy.c, g.c, 1e-9 * scale);
    EXPECT_NEAR(proxy.d, g.d, 1e-9 * scale);
  }
}

TEST(SymmetricDirichlet, TheFlatLayoutOfAPlaneIsAnIsometry) {
  const TriMesh mesh = testing::flatGrid(5, testing::GridPattern::Jittered);
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.positions()) uv.push_back({p.x, p.y});
  const std::vector<FaceGradient> g = faceGradients(mesh, false);
  EXPECT_NEAR(dirichletSums(mesh, g, uv).perUnitArea(), 4.0, 1e-12);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) EXPECT_NEAR(jacobian(g[f], mesh.triangle(f), uv).det(), 1.0, 1e-12);
}

TEST(SymmetricDirichlet, TheFlipFreeStepEndsWhereAFaceCollapses) {
  // One triangle (0,0), (1,0), (0,1); moving the apex straight down collapses it at t = 1 (a linear
  // area), moving it down and sideways too (a quadratic area when two corners move).
  const TriMesh mesh = testing::buildOrFail({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const std::vector<Vec2> uv{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_NEAR(largestFlipFreeStep(mesh, uv, {{0, 0}, {0, 0}, {0, -1}}), 1.0, 1e-15);
  EXPECT_TRUE(std::isinf(largestFlipFreeStep(mesh, uv, {{0, 0}, {0, 0}, {0, 1}})));
  // Corner 1 moves to (1 − t, 0) and corner 2 to (0, 1 − 2t): area ∝ (1 − t)(1 − 2t), first zero at 1/2.
  EXPECT_NEAR(largestFlipFreeStep(mesh, uv, {{0, 0}, {-1, 0}, {0, -2}}), 0.5, 1e-15);
  // Corners moving to (1 − t, t) and (−t, 1 − t): area ∝ (1 − t)² + t², never zero.
  EXPECT_TRUE(std::isinf(largestFlipFreeStep(mesh, uv, {{0, 0}, {-1, 1}, {-1, -1}})));
}

TEST(SymmetricDirichlet, ADegenerateFaceCarriesNoEnergyUnlessRegularized) {
  // A sliver (b, a, m) with m the midpoint of a → b: no 3D area.
  const TriMesh mesh = testing::buildOrFail({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}}, {{0, 1, 2}, {1, 0, 3}});
  ASSERT_TRUE(mesh.isDegenerateFace(1));
  EXPECT_EQ(faceGradients(mesh, false)[1].area, 0.0);
  const FaceGradient regular = faceGradients(mesh, true)[1];
  EXPECT_NEAR(regular.area, 0.5, 1e-12);  // the mean area of the measurable faces
  EXPECT_TRUE(std::isfinite(regular.gx[0]) && std::isfinite(regular.gy[2]));
}

}  // namespace
}  // namespace straightest
