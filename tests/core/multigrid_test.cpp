// The smoothed-aggregation hierarchy: it coarsens down to a direct solve, its V-cycle is a fixed
// linear operator that shrinks the error on its own — also where its Gauss–Seidel sweeps run in
// blocks, in a mesh's numbering and in a scattered one — its setup reports progress and can be
// cancelled, and a matrix it cannot handle is refused without an error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solver_systems.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/solver/multigrid.hpp"

namespace straightest {
namespace {

using testing::circleSystem;
using testing::columnResidual;
using testing::scattered;

/// b1, b2 and 2 b1 − 3 b2 through one V-cycle each: the third equals 2 x1 − 3 x2 (a fixed linear
/// operator keeps nothing from one call to the next).
void expectLinear(const AggregationMultigrid& mg, size_t m) {
  std::vector<double> b1(m), b2(m), sum(m), x1(m), x2(m), xs(m);
  for (size_t i = 0; i < m; ++i) {
    b1[i] = std::sin(0.1 * i);
    b2[i] = std::cos(0.37 * i);
    sum[i] = 2 * b1[i] - 3 * b2[i];
  }
  mg.apply(b1.data(), x1.data());
  mg.apply(b2.data(), x2.data());
  mg.apply(sum.data(), xs.data());
  double scale = 0;
  for (size_t i = 0; i < m; ++i) scale = std::max(scale, std::abs(xs[i]));
  for (size_t i = 0; i < m; ++i) ASSERT_NEAR(xs[i], 2 * x1[i] - 3 * x2[i], 1e-12 * scale) << "entry " << i;
}

/// The relative residuals of both columns after `cycles` steps x ← x + M(b − A x) from x = 0.
std::vector<double> stationaryResiduals(const AggregationMultigrid& mg, const InteriorSystem& s, int cycles) {
  const size_t m = s.rhs.size();
  std::vector<double> x(m, 0.0), r(m), e(m), Ax(m);
  for (int cycle = 0; cycle < cycles; ++cycle) {
    s.A.multiply2(x.data(), Ax.data());
    for (size_t i = 0; i < m; ++i) r[i] = s.rhs[i] - Ax[i];
    mg.apply(r.data(), e.data());
    for (size_t i = 0; i < m; ++i) x[i] += e[i];
  }
  return {columnResidual(s.A, s.rhs, x, 0), columnResidual(s.A, s.rhs, x, 1)};
}

TEST(Multigrid, CoarsensToTheDirectSolveSizeReportingMonotoneProgress) {
  const InteriorSystem s = circleSystem(makeHeightField(100));
  AggregationMultigrid mg;
  std::vector<double> fractions;
  auto built = mg.compute(s.A, [&](const char* stage, double f) {
    EXPECT_STREQ(stage, "solve");
    fractions.push_back(f);
    return true;
  });
  ASSERT_TRUE(built.ok());
  ASSERT_TRUE(built.value());
  EXPECT_TRUE(mg.ok());
  EXPECT_GE(mg.levels(), 3);
  const std::vector<int32_t> sizes = mg.sizes();
  EXPECT_EQ(sizes.front(), s.A.rows);
  for (size_t l = 1; l < sizes.size(); ++l) EXPECT_LT(sizes[l], sizes[l - 1]);
  EXPECT_LE(sizes.back(), AggregationMultigrid::kCoarseSize);
  ASSERT_FALSE(fractions.empty());
  for (size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
  EXPECT_GT(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  // It keeps the matrix, rows sorted by column: the same matrix (the same entries, the same products).
  const CsrMatrix& kept = mg.matrix();
  ASSERT_EQ(kept.nonZeros(), s.A.nonZeros());
  std::vector<double> x(s.rhs.size()), y1(x.size()), y2(x.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.3 * i);
  kept.multiply2(x.data(), y1.data());
  s.A.multiply2(x.data(), y2.data());
  for (size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(y1[i], y2[i], 1e-14);
  for (int32_t r = 0; r < kept.rows; ++r)
    for (int32_t k = kept.start[r] + 1; k < kept.start[r + 1]; ++k) ASSERT_LT(kept.col[k - 1], kept.col[k]);
}

TEST(Multigrid, VCycleIsALinearOperator) {
  const InteriorSystem s = circleSystem(makeHeightField(40));
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.compute(s.A).value());
  expectLinear(mg, s.rhs.size());
}

TEST(Multigrid, SweepsInBlocksKeepTheCycleLinearAndConvergentInAMeshsNumberingAndAScatteredOne) {
  // 78k rows: the finest level's sweeps run in four blocks of rows plus the rows on their borders
  // (few in the height field's numbering, nearly all in the scattered one). A border row read before
  // the sweep wrote it, or a block reading another, would make a cycle depend on the one before or on
  // the order the blocks ran in, and spoil the linearity or the convergence.
  const InteriorSystem mesh = circleSystem(makeHeightField(280));
  ASSERT_GT(mesh.A.rows, 4 * 16384);
  for (const InteriorSystem& s : {mesh, scattered(mesh, 7)}) {
    AggregationMultigrid mg;
    ASSERT_TRUE(mg.compute(s.A).value());
    expectLinear(mg, s.rhs.size());
    for (const double residual : stationaryResiduals(mg, s, 30)) EXPECT_LT(residual, 1e-6);
  }
}

TEST(Multigrid, RepeatedVCyclesAloneConvergeWithEitherSmoother) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  for (auto smoother : {AggregationMultigrid::Smoother::GaussSeidel, AggregationMultigrid::Smoother::Jacobi}) {
    AggregationMultigrid mg({smoother, 2, 2});
    ASSERT_TRUE(mg.compute(s.A).value());
    for (const double residual : stationaryResiduals(mg, s, 20))
      EXPECT_LT(residual, 1e-6) << static_cast<int>(smoother);
  }
}

TEST(Multigrid, CancelledSetupIsACancelledError) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  AggregationMultigrid mg;
  int calls = 0;
  double stoppedAt = -1;
  auto built = mg.compute(s.A, [&](const char*, double f) {
    ++calls;
    stoppedAt = f;
    return false;
  });
  ASSERT_FALSE(built.ok());
  EXPECT_EQ(built.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 1);
  EXPECT_LT(stoppedAt, 1.0);  // after the first level, not at the end
  EXPECT_FALSE(mg.ok());
}

TEST(Multigrid, AZeroDiagonalIsRefusedWithoutAnError) {
  // [[0, 1], [1, 0]]: invertible, but Gauss–Seidel and Jacobi divide by the diagonal.
  AggregationMultigrid mg;
  auto built = mg.compute(testing::fromRows(2, {{{1, 1.0}}, {{0, 1.0}}}));
  ASSERT_TRUE(built.ok());
  EXPECT_FALSE(built.value());
  EXPECT_FALSE(mg.ok());
  EXPECT_EQ(mg.matrix().rows, 2);  // still there for whoever solves it otherwise
}

}  // namespace
}  // namespace straightest
