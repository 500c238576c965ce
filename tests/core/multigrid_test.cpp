// The smoothed-aggregation hierarchy: it coarsens down to a direct solve, its V-cycle is a fixed
// linear operator that shrinks the error on its own, its setup reports progress and can be
// cancelled, and a matrix it cannot handle is refused without an error.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver_systems.hpp"
#include "straightest/multigrid.hpp"
#include "straightest/samples.hpp"

namespace straightest {
namespace {

using testing::circleSystem;
using testing::columnResidual;

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
  const size_t m = s.rhs.size();
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
  for (size_t i = 0; i < m; ++i) ASSERT_NEAR(xs[i], 2 * x1[i] - 3 * x2[i], 1e-12 * scale);
}

TEST(Multigrid, RepeatedVCyclesAloneConvergeWithEitherSmoother) {
  const InteriorSystem s = circleSystem(makeHeightField(60));
  for (auto smoother : {AggregationMultigrid::Smoother::GaussSeidel, AggregationMultigrid::Smoother::Jacobi}) {
    AggregationMultigrid mg({smoother, 2, 2});
    ASSERT_TRUE(mg.compute(s.A).value());
    // Stationary iteration x ← x + M(b − A x).
    const size_t m = s.rhs.size();
    std::vector<double> x(m, 0.0), r(m), e(m), Ax(m);
    for (int cycle = 0; cycle < 20; ++cycle) {
      s.A.multiply2(x.data(), Ax.data());
      for (size_t i = 0; i < m; ++i) r[i] = s.rhs[i] - Ax[i];
      mg.apply(r.data(), e.data());
      for (size_t i = 0; i < m; ++i) x[i] += e[i];
    }
    for (int c = 0; c < 2; ++c) EXPECT_LT(columnResidual(s.A, s.rhs, x, c), 1e-6) << static_cast<int>(smoother);
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
