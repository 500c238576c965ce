// The one linear-solve entry point: every backend gives the direct solution of the parameterization's
// system; an iterative backend that cannot solve falls back to the direct one; a singular matrix gives
// an infinite residual, not a crash; progress stays within 0..1, setup first, never going back; a
// progress that says stop, in the setup or in the iterations, is a Cancelled error.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "solver_systems.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "straightest/solver/linear_solve.hpp"

namespace straightest {
namespace {

using testing::circleSystem;

/// The uv map of `mesh` whose interior is the solution x of its circle system.
std::vector<Vec2> circleMap(const TriMesh& mesh, const std::vector<double>& x) {
  const InteriorWeights W = interiorWeights(mesh, WeightKind::ShapePreserving);
  const BoundaryMap boundary = circleBoundary(mesh);
  std::vector<Vec2> uv(mesh.numVertices(), Vec2{0, 0});
  for (size_t i = 0; i < boundary.loop.size(); ++i) uv[boundary.loop[i]] = boundary.polygon[i];
  for (size_t r = 0; r < W.rows.size(); ++r) uv[W.rows[r]] = {x[2 * r], x[2 * r + 1]};
  return uv;
}

TEST(LinearSolve, EveryBackendGivesTheDirectSolution) {
  const TriMesh mesh = makeHeightField(120);
  const InteriorSystem s = circleSystem(mesh);
  std::vector<double> exact(s.rhs.size(), 0.0);
  auto lu = solve(s.A, s.rhs, exact, LinearSolver::SparseLU);
  ASSERT_TRUE(lu.ok());
  EXPECT_EQ(lu.value().used, LinearSolver::SparseLU);
  EXPECT_EQ(lu.value().iterations, 0);
  EXPECT_LT(lu.value().residual, 1e-12);
  const StretchMetrics exactMetrics = textureStretch(mesh, circleMap(mesh, exact));
  ASSERT_TRUE(exactMetrics.bijective);
  for (LinearSolver backend : {LinearSolver::Multigrid, LinearSolver::BiCGSTAB}) {
    std::vector<double> x(s.rhs.size(), 0.0);
    auto stats = solve(s.A, s.rhs, x, backend);
    ASSERT_TRUE(stats.ok());
    EXPECT_EQ(stats.value().used, backend);  // converged: no fallback
    EXPECT_GT(stats.value().iterations, 0);
    EXPECT_LT(stats.value().residual, 1e-9);
    for (size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(x[i], exact[i], 1e-8) << static_cast<int>(backend);
    EXPECT_NEAR(textureStretch(mesh, circleMap(mesh, x)).l2, exactMetrics.l2, 1e-9);
  }
}

TEST(LinearSolve, FallsBackToTheDirectSolveWhenTheMultigridCannotHandleTheMatrix) {
  // A circulant with a zero diagonal: invertible (its eigenvalues ω(2 + ω), |ω| = 1, are not 0), but
  // no smoother can divide by its diagonal.
  const int32_t n = 50;
  std::vector<std::vector<std::pair<int32_t, double>>> rows(n);
  for (int32_t i = 0; i < n; ++i) rows[i] = {{(i + 1) % n, 2.0}, {(i + 2) % n, 1.0}};
  const CsrMatrix A = testing::fromRows(n, rows);
  std::vector<double> expected(2 * n), rhs(2 * n);
  for (size_t i = 0; i < expected.size(); ++i) expected[i] = std::sin(1.0 + i);
  A.multiply2(expected.data(), rhs.data());
  for (LinearSolver backend : {LinearSolver::Multigrid, LinearSolver::BiCGSTAB}) {
    std::vector<double> x(2 * n, 0.0);
    auto stats = solve(A, rhs, x, backend);
    ASSERT_TRUE(stats.ok());
    if (backend == LinearSolver::Multigrid) {
      EXPECT_EQ(stats.value().used, LinearSolver::SparseLU);
    }
    EXPECT_LT(stats.value().residual, 1e-9);
    for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], expected[i], 1e-8);
  }
}

TEST(LinearSolve, ASingularMatrixGivesZerosAndAnInfiniteResidual) {
  // Two equal rows and right-hand sides that differ on them: no solution for any backend.
  const CsrMatrix A = testing::fromRows(2, {{{0, 1.0}, {1, 1.0}}, {{0, 1.0}, {1, 1.0}}});
  const std::vector<double> rhs = {1, 0, 0, 1};
  for (LinearSolver backend : {LinearSolver::Multigrid, LinearSolver::SparseLU, LinearSolver::BiCGSTAB}) {
    std::vector<double> x(4, 0.5);
    auto stats = solve(A, rhs, x, backend);
    ASSERT_TRUE(stats.ok());
    EXPECT_EQ(stats.value().residual, std::numeric_limits<double>::infinity()) << static_cast<int>(backend);
    EXPECT_EQ(x, std::vector<double>(4, 0.0));
  }
}

TEST(LinearSolve, ProgressStaysWithinZeroAndOneSetupFirstAndNeverGoesBack) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  for (LinearSolver backend : {LinearSolver::Multigrid, LinearSolver::BiCGSTAB}) {
    std::vector<double> fractions;
    std::vector<double> x(s.rhs.size(), 0.0);
    auto stats = solve(s.A, s.rhs, x, backend, [&](const char* stage, double f) {
      EXPECT_STREQ(stage, "solve");
      fractions.push_back(f);
      return true;
    });
    ASSERT_TRUE(stats.ok());
    ASSERT_FALSE(fractions.empty());
    EXPECT_GT(fractions.front(), 0.0);
    EXPECT_LE(fractions.front(), kSetupShare + 1e-12);  // the setup reports first, within its share
    for (size_t i = 0; i < fractions.size(); ++i) {
      EXPECT_GE(fractions[i], 0.0);
      EXPECT_LE(fractions[i], 1.0);
      if (i > 0) {
        EXPECT_GE(fractions[i], fractions[i - 1]);
      }
    }
    if (backend == LinearSolver::Multigrid) {
      EXPECT_GT(fractions.back(), kSetupShare);  // the iterations report past the setup's share
      EXPECT_NEAR(fractions.back(), 1.0, 1e-12);
    }
  }
}

TEST(LinearSolve, StoppingInTheSetupOrInTheIterationsIsACancelledError) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  struct Case {
    LinearSolver backend;
    bool inSetup;
  };
  for (const Case& c : {Case{LinearSolver::Multigrid, true}, Case{LinearSolver::Multigrid, false},
                        Case{LinearSolver::BiCGSTAB, true}}) {
    std::vector<double> x(s.rhs.size(), 0.0);
    double stoppedAt = -1;
    auto stats = solve(s.A, s.rhs, x, c.backend, [&](const char*, double f) {
      const bool stop = c.inSetup ? f <= kSetupShare : f > kSetupShare;
      if (stop) stoppedAt = f;
      return !stop;
    });
    ASSERT_FALSE(stats.ok());
    EXPECT_EQ(stats.error().code, ErrorCode::Cancelled);
    if (c.inSetup) {
      EXPECT_LE(stoppedAt, kSetupShare);
    } else {
      EXPECT_LT(stoppedAt, 1.0);  // mid-iteration, before convergence
    }
  }
}

TEST(LinearSolve, AMalformedMatrixOrSizesThatDoNotFitAreAnInvalidArgument) {
  const CsrMatrix A = testing::fromRows(2, {{{0, 1.0}}, {{1, 1.0}}});
  std::vector<double> x(4, 0.0);
  auto wrongRhs = solve(A, std::vector<double>(3, 1.0), x, LinearSolver::SparseLU);
  ASSERT_FALSE(wrongRhs.ok());
  EXPECT_EQ(wrongRhs.error().code, ErrorCode::InvalidArgument);
  const CsrMatrix notSquare = testing::fromRows(3, {{{0, 1.0}}, {{1, 1.0}}});
  EXPECT_FALSE(solve(notSquare, std::vector<double>(4, 1.0), x, LinearSolver::Multigrid).ok());
  CsrMatrix outside = A;
  outside.col[1] = 2;  // column 2 of a 2 × 2 matrix
  auto malformed = solve(outside, std::vector<double>(4, 1.0), x, LinearSolver::Multigrid);
  ASSERT_FALSE(malformed.ok());
  EXPECT_EQ(malformed.error().code, ErrorCode::InvalidArgument);
}

TEST(LinearSolve, BackendNamesParseAndUnknownOnesAreRefused) {
  EXPECT_EQ(parseLinearSolver("multigrid").value(), LinearSolver::Multigrid);
  EXPECT_EQ(parseLinearSolver("lu").value(), LinearSolver::SparseLU);
  EXPECT_EQ(parseLinearSolver("bicgstab").value(), LinearSolver::BiCGSTAB);
  auto unknown = parseLinearSolver("cg");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().code, ErrorCode::InvalidArgument);
}

}  // namespace
}  // namespace straightest
