// SLIM's global step (private: core/src/slim_global_step.hpp): with every face's target the rotation
// of an isometric layout, the step returns that layout (up to translation) from any start, by either
// solver; and the multigrid-preconditioned conjugate gradients agree with the factorization.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "../../core/param/src/free/slim_global_step.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

struct System {
  std::vector<FaceGradient> gradients;
  std::vector<Mat2> weights, rotations;
};

/// Targets: each face's Jacobian in `layout`; weights: SPD matrices varying from face to face.
System targetsFrom(const TriMesh& mesh, const std::vector<Vec2>& layout) {
  System s;
  s.gradients = faceGradients(mesh, false);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> w(1, 8), off(-0.5, 0.5);
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    s.rotations.push_back(jacobian(s.gradients[f], mesh.triangle(f), layout));
    const double a = w(rng), d = w(rng), b = off(rng);
    s.weights.push_back({a, b, b, d});
  }
  return s;
}

/// uv minus its mean.
std::vector<Vec2> centred(std::vector<Vec2> uv) {
  Vec2 mean;
  for (const Vec2& q : uv) mean += q / double(uv.size());
  for (Vec2& q : uv) q -= mean;
  return uv;
}

void expectLayout(const std::vector<Vec2>& solved, const std::vector<Vec2>& layout, double tolerance) {
  const std::vector<Vec2> a = centred(solved), b = centred(layout);
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_NEAR(a[i].x, b[i].x, tolerance) << "vertex " << i;
    ASSERT_NEAR(a[i].y, b[i].y, tolerance) << "vertex " << i;
  }
}

TEST(SlimGlobalStep, RecoversAnIsometricLayoutByEitherSolver) {
  const TriMesh mesh = testing::flatGrid(12, testing::GridPattern::Jittered);
  std::vector<Vec2> layout, start;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  for (const Vec3& p : mesh.positions()) {
    // The plane rotated by 0.3 rad: the targets are rotations, the layout an isometry.
    layout.push_back({std::cos(0.3) * p.x - std::sin(0.3) * p.y, std::sin(0.3) * p.x + std::cos(0.3) * p.y});
    start.push_back(layout.back() + Vec2{noise(rng), noise(rng)});
  }
  const System s = targetsFrom(mesh, layout);
  for (int32_t directSize : {mesh.numVertices(), 0}) {  // factorization, then conjugate gradients
    SCOPED_TRACE(directSize);
    SlimGlobalStep step(mesh, directSize);
    std::vector<Vec2> next;
    ASSERT_TRUE(step.solve(s.gradients, s.weights, s.rotations, start, next));
    expectLayout(next, layout, 1e-5);
    if (directSize == 0) {
      EXPECT_GT(step.lastIterations(), 0);
    }
  }
}

TEST(SlimGlobalStep, ConjugateGradientsAgreeWithTheFactorizationOnACurvedPatch) {
  // Targets that no map meets exactly (a bumpy surface): the two solvers still find the same minimizer.
  const TriMesh mesh = testing::almostFlatGrid(14, 0.8);
  std::vector<Vec2> start;
  for (const Vec3& p : mesh.positions()) start.push_back({p.x * 0.9, p.y * 1.1});
  System s = targetsFrom(mesh, start);
  for (Mat2& r : s.rotations) r = {1, 0, 0, 1};
  SlimGlobalStep direct(mesh, mesh.numVertices()), iterative(mesh, 0);
  std::vector<Vec2> a, b;
  ASSERT_TRUE(direct.solve(s.gradients, s.weights, s.rotations, start, a));
  ASSERT_TRUE(iterative.solve(s.gradients, s.weights, s.rotations, start, b));
  expectLayout(b, a, 1e-4);
}

}  // namespace
}  // namespace straightest
