// The solver on several threads and with reused work space: the multigrid-preconditioned solve, its
// V-cycle (either smoother; Gauss–Seidel sweeping blocks of rows on several threads), the two-column product and a
// whole parameterization give the same bits with 1, 2 and 3 threads (their loops run in fixed row chunks and add
// per-chunk sums in chunk order); solving a smaller system after a larger one — the same objects, their buffers already
// grown — gives exactly what solving the smaller one first gave.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver_systems.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/solver/krylov.hpp"
#include "straightest/solver/linear_solve.hpp"
#include "straightest/solver/multigrid.hpp"

namespace straightest {
namespace {

using testing::circleSystem;
using testing::scattered;

/// Restores the process-wide thread count (every hardware thread) when the test ends.
struct ThreadCountGuard {
  ~ThreadCountGuard() { setThreadCount(0); }
};

/// x of A x = b by the default backend (multigrid + BiCGSTAB) from the zero guess, and its stats.
std::vector<double> solveWith(const InteriorSystem& s, LinearSolveStats* stats = nullptr) {
  std::vector<double> x(s.rhs.size(), 0.0);
  auto solved = solve(s.A, s.rhs, x, LinearSolver::Multigrid);
  EXPECT_TRUE(solved.ok());
  if (stats && solved) *stats = solved.value();
  return x;
}

/// Bitwise equality (EXPECT_EQ on doubles is exact): the first difference is reported.
void expectSameBits(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "entry " << i;
}

TEST(SolverThreads, TheSolveIsBitIdenticalForOneTwoAndThreeThreads) {
  ThreadCountGuard guard;
  // 40k interior rows: several row chunks, so a second thread has chunks of its own.
  const InteriorSystem s = circleSystem(makeHeightField(200));
  ASSERT_GT(s.A.rows, 4 * 8192);
  setThreadCount(1);
  LinearSolveStats one;
  const std::vector<double> x1 = solveWith(s, &one);
  EXPECT_EQ(one.used, LinearSolver::Multigrid);
  EXPECT_LT(one.residual, 1e-9);
  for (int threads : {2, 3}) {
    setThreadCount(threads);
    LinearSolveStats many;
    const std::vector<double> xt = solveWith(s, &many);
    EXPECT_EQ(many.iterations, one.iterations) << threads << " threads";
    EXPECT_EQ(many.residual, one.residual) << threads << " threads";
    expectSameBits(x1, xt);
  }
}

TEST(SolverThreads, TheProductAndTheVCycleAreBitIdenticalForAnyThreadCountWithEitherSmoother) {
  ThreadCountGuard guard;
  // 40k rows: the finest Gauss–Seidel sweeps run in two blocks, which threads may take in any order;
  // in the scattered numbering nearly every row is on a block's border.
  const InteriorSystem mesh = circleSystem(makeHeightField(200));
  ASSERT_GT(mesh.A.rows, 2 * 16384);
  for (const InteriorSystem& s : {mesh, scattered(mesh, 3)}) {
    std::vector<double> b(s.rhs.size());
    for (size_t i = 0; i < b.size(); ++i) b[i] = std::sin(0.01 * i) + 0.3 * std::cos(0.7 * i);
    for (auto smoother : {AggregationMultigrid::Smoother::GaussSeidel, AggregationMultigrid::Smoother::Jacobi}) {
      std::vector<double> reference;
      for (int threads : {1, 2, 3}) {
        setThreadCount(threads);
        AggregationMultigrid mg({smoother, 1, 1});
        ASSERT_TRUE(mg.compute(s.A).value());
        std::vector<double> x(b.size()), Ax(b.size());
        mg.apply(b.data(), x.data());
        mg.matrix().multiply2(x.data(), Ax.data());
        x.insert(x.end(), Ax.begin(), Ax.end());
        if (reference.empty()) reference = x;
        else expectSameBits(reference, x);
      }
    }
  }
}

TEST(SolverThreads, AParameterizationIsBitIdenticalForOneAndTwoThreads) {
  ThreadCountGuard guard;
  const TriMesh mesh = makeHeightField(120);
  std::vector<Parameterization> maps;
  for (int threads : {1, 2}) {
    setThreadCount(threads);
    auto p = parameterize(mesh, ParamOptions{});
    ASSERT_TRUE(p.ok());
    EXPECT_TRUE(p.value().metrics.bijective);
    maps.push_back(std::move(p).value());
  }
  ASSERT_EQ(maps[0].uv.size(), maps[1].uv.size());
  for (size_t v = 0; v < maps[0].uv.size(); ++v) {
    ASSERT_EQ(maps[0].uv[v].x, maps[1].uv[v].x) << "vertex " << v;
    ASSERT_EQ(maps[0].uv[v].y, maps[1].uv[v].y) << "vertex " << v;
  }
  EXPECT_EQ(maps[0].metrics.l2, maps[1].metrics.l2);
  EXPECT_EQ(maps[0].residual, maps[1].residual);
}

TEST(SolverThreads, ASmallerSystemAfterALargerOneGivesWhatItGaveFirst) {
  const InteriorSystem small = circleSystem(makeHeightField(60));
  const InteriorSystem large = circleSystem(makeHeightField(130));
  // Through the solve entry point: small, large, small again.
  const std::vector<double> first = solveWith(small);
  (void)solveWith(large);
  expectSameBits(first, solveWith(small));
  // One multigrid object recomputed on another matrix (its levels' buffers already sized for the
  // larger one) cycles exactly as a fresh object on that matrix.
  std::vector<double> b(small.rhs.size());
  for (size_t i = 0; i < b.size(); ++i) b[i] = std::cos(0.05 * i);
  AggregationMultigrid fresh;
  ASSERT_TRUE(fresh.compute(small.A).value());
  std::vector<double> expected(b.size()), got(b.size());
  fresh.apply(b.data(), expected.data());
  AggregationMultigrid reused;
  ASSERT_TRUE(reused.compute(large.A).value());
  ASSERT_TRUE(reused.compute(small.A).value());
  EXPECT_EQ(reused.sizes(), fresh.sizes());
  reused.apply(b.data(), got.data());
  expectSameBits(expected, got);
  // And a whole parameterization of the small mesh after the large one.
  const TriMesh smallMesh = makeHeightField(60), largeMesh = makeHeightField(130);
  auto before = parameterize(smallMesh, ParamOptions{});
  ASSERT_TRUE(before.ok());
  ASSERT_TRUE(parameterize(largeMesh, ParamOptions{}).ok());
  auto after = parameterize(smallMesh, ParamOptions{});
  ASSERT_TRUE(after.ok());
  ASSERT_EQ(before.value().uv.size(), after.value().uv.size());
  for (size_t v = 0; v < before.value().uv.size(); ++v) {
    ASSERT_EQ(before.value().uv[v].x, after.value().uv[v].x) << "vertex " << v;
    ASSERT_EQ(before.value().uv[v].y, after.value().uv[v].y) << "vertex " << v;
  }
}

}  // namespace
}  // namespace straightest
