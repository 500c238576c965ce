// The two-column BiCGSTAB: with a multigrid V-cycle it solves the ill-conditioned interior system in
// a few iterations (without it, not), each column on its own schedule, reporting monotone progress
// once per iteration; a progress that says stop is a Cancelled error.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "solver_systems.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/solver/krylov.hpp"
#include "straightest/solver/multigrid.hpp"

namespace straightest {
namespace {

using testing::circleSystem;
using testing::columnResidual;

TwoColumnPreconditioner vCycle(const AggregationMultigrid& mg) {
  return [&mg](const double* b, double* x) { mg.apply(b, x); };
}

TEST(Krylov, MultigridPreconditionedConvergesInFewIterationsOnTheIllConditionedSystem) {
  const InteriorSystem s = circleSystem(makeHeightField(100));
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.compute(s.A).value());
  std::vector<double> x(s.rhs.size(), 0.0);
  std::vector<double> fractions;
  auto stats = solveTwoColumns(mg.matrix(), vCycle(mg), s.rhs, x, 1e-10, 1000, [&](const char* stage, double f) {
    EXPECT_STREQ(stage, "solve");
    fractions.push_back(f);
    return true;
  });
  ASSERT_TRUE(stats.ok());
  ASSERT_TRUE(stats.value().converged);
  EXPECT_LE(stats.value().iterations, 15);  // ~8–10 seen at 10k–1M vertices; thousands without multigrid
  EXPECT_EQ(static_cast<int>(fractions.size()), stats.value().iterations);  // one report per iteration
  for (size_t i = 0; i < fractions.size(); ++i) {
    EXPECT_GE(fractions[i], 0.0);
    EXPECT_LE(fractions[i], 1.0);
    if (i > 0) {
      EXPECT_GE(fractions[i], fractions[i - 1]);
    }
  }
  EXPECT_NEAR(fractions.back(), 1.0, 1e-12);
  for (int c = 0; c < 2; ++c) {
    EXPECT_LE(stats.value().relativeResidual[c], 1e-10);
    EXPECT_LT(columnResidual(s.A, s.rhs, x, c), 1e-9);  // the true residual, not the recurrence's
  }
}

TEST(Krylov, WithoutAPreconditionerTheSameIterationsAreFarFromEnough) {
  const InteriorSystem s = circleSystem(makeHeightField(100));
  std::vector<double> x(s.rhs.size(), 0.0);
  const TwoColumnPreconditioner identity = [n = s.rhs.size()](const double* b, double* y) { std::copy(b, b + n, y); };
  auto stats = solveTwoColumns(s.A, identity, s.rhs, x, 1e-10, 15);
  ASSERT_TRUE(stats.ok());
  EXPECT_FALSE(stats.value().converged);
  EXPECT_EQ(stats.value().iterations, 15);
  EXPECT_GT(std::max(columnResidual(s.A, s.rhs, x, 0), columnResidual(s.A, s.rhs, x, 1)), 1e-6);
}

TEST(Krylov, ColumnsConvergeIndependentlyAndAZeroColumnIsSolvedExactly) {
  InteriorSystem s = circleSystem(makeHeightField(40));
  for (size_t i = 1; i < s.rhs.size(); i += 2) s.rhs[i] = 0;  // v column: b = 0 → x = 0
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.compute(s.A).value());
  std::vector<double> x(s.rhs.size(), 0.25);
  auto stats = solveTwoColumns(mg.matrix(), vCycle(mg), s.rhs, x, 1e-10, 1000);
  ASSERT_TRUE(stats.ok());
  ASSERT_TRUE(stats.value().converged);
  for (size_t i = 1; i < x.size(); i += 2) ASSERT_EQ(x[i], 0.0);
  EXPECT_LT(columnResidual(s.A, s.rhs, x, 0), 1e-9);
}

TEST(Krylov, AProgressThatSaysStopMidIterationIsACancelledError) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.compute(s.A).value());
  std::vector<double> x(s.rhs.size(), 0.0);
  int calls = 0;
  auto stats = solveTwoColumns(mg.matrix(), vCycle(mg), s.rhs, x, 1e-10, 1000,
                               [&](const char*, double) { return ++calls < 3; });
  ASSERT_FALSE(stats.ok());
  EXPECT_EQ(stats.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace straightest
