// linear_solve.cpp — the backend dispatch and the fallback to the direct solve; the two Eigen
// backends (SparseLU, BiCGSTAB with ILUT) are thin wrappers here, the multigrid one lives in
// multigrid.cpp and krylov.cpp.
#include "straightest/solver/linear_solve.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "row_chunks.hpp"
#include "solve_progress.hpp"
#include "straightest/solver/eigen_bridge.hpp"
#include "straightest/solver/krylov.hpp"
#include "straightest/solver/multigrid.hpp"

namespace straightest {
namespace {

/// Multigrid-preconditioned two-column BiCGSTAB. Moves A into `multigrid` (its matrix() serves the
/// fallback and the residual afterwards). Returns whether it converged.
Expected<bool> multigridSolve(CsrMatrix A, const std::vector<double>& rhs, std::vector<double>& x,
                              const Progress& progress, AggregationMultigrid& multigrid, int& iterations) {
  auto built = multigrid.compute(std::move(A), progress.range(0, kSetupShare));
  if (!built) return built.error();
  if (!built.value()) return false;
  const AggregationMultigrid& M = multigrid;
  auto stats = solveTwoColumns(
      multigrid.matrix(), [&M](const double* b, double* y) { M.apply(b, y); }, rhs, x, kSolveTolerance,
      kSolveMaxIterations, progress.range(kSetupShare, 1));
  if (!stats) return stats.error();
  iterations = stats.value().iterations;
  return stats.value().converged;
}

/// Eigen's BiCGSTAB with incomplete LU, one column at a time; iterations in chunks of 10 so progress
/// can be reported (and cancelled) as the residual falls. Returns whether both columns converged.
Expected<bool> ilutSolve(const CsrMatrix& A, const std::vector<double>& rhs, std::vector<double>& x,
                         const Progress& progress, int& iterations) {
  const int32_t n = A.rows;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> M = toEigen(A);
  Eigen::BiCGSTAB<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::IncompleteLUT<double>> it;
  it.preconditioner().setFillfactor(4);
  it.setTolerance(kSolveTolerance);
  it.setMaxIterations(10);
  it.compute(M);
  if (it.info() != Eigen::Success) return false;
  if (!progress(kSolveStage, kSetupShare)) return cancelledError("linear solve");
  for (int c = 0; c < 2; ++c) {
    Eigen::VectorXd b(n), xc(n);
    for (int32_t r = 0; r < n; ++r) {
      b[r] = rhs[2 * r + c];
      xc[r] = x[2 * r + c];
    }
    const double r0 = std::max((M * xc - b).norm() / std::max(b.norm(), 1e-300), 1e-300);
    const Progress columnProgress = progress.range(kSetupShare, 1).range(0.5 * c, 0.5 * (c + 1));
    ResidualProgress report(columnProgress, r0, kSolveTolerance);
    for (int chunk = 0;; ++chunk) {
      xc = it.solveWithGuess(b, xc);
      iterations += static_cast<int>(it.iterations());
      if (it.info() == Eigen::Success) break;
      if (chunk >= kSolveMaxIterations / 10 || !std::isfinite(it.error())) return false;
      if (!report(it.error())) return cancelledError("linear solve");
    }
    for (int32_t r = 0; r < n; ++r) x[2 * r + c] = xc[r];
  }
  return true;
}

/// Eigen's SparseLU (COLAMD) for both columns at once; false if A is singular.
bool directSolve(const CsrMatrix& A, const std::vector<double>& rhs, std::vector<double>& x) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(toEigen(A));
  if (lu.info() != Eigen::Success) return false;
  solveInterleaved(lu, rhs, x);
  return true;
}

/// |A x − b| / |b| over both columns (|A x − b| when b = 0).
double relativeResidual(const CsrMatrix& A, const std::vector<double>& rhs, const std::vector<double>& x) {
  std::vector<double> Ax(x.size());
  A.multiply2(x.data(), Ax.data());
  // Per-chunk sums added in chunk order: the same bits for any thread count.
  const auto sums = detail::sumRowChunks<2>(x.size(), [&](size_t begin, size_t end, double* sum) {
    double res2 = 0, b2 = 0;
    for (size_t i = begin; i < end; ++i) {
      res2 += (Ax[i] - rhs[i]) * (Ax[i] - rhs[i]);
      b2 += rhs[i] * rhs[i];
    }
    sum[0] = res2;
    sum[1] = b2;
  });
  const double res2 = sums[0], b2 = sums[1];
  return b2 > 0 ? std::sqrt(res2 / b2) : std::sqrt(res2);
}

}  // namespace

Expected<LinearSolveStats> solve(CsrMatrix A, const std::vector<double>& rhs, std::vector<double>& x,
                                 LinearSolver solver, const Progress& progress) {
  const size_t unknowns = 2 * static_cast<size_t>(std::max(A.rows, 0));
  if (!wellFormed(A) || A.rows != A.cols || rhs.size() != unknowns || x.size() != unknowns)
    return Error{ErrorCode::InvalidArgument,
                 "linear solve: needs a well-formed square matrix and two values per row in the right-hand side "
                 "and the solution (got " +
                     std::to_string(A.rows) + " by " + std::to_string(A.cols) + ", " + std::to_string(rhs.size()) +
                     " and " + std::to_string(x.size()) + " values)"};
  LinearSolveStats stats;
  stats.used = solver;
  if (A.rows == 0) return stats;
  AggregationMultigrid multigrid;
  const CsrMatrix* kept = &A;  // the matrix after the backend: the multigrid keeps A (rows sorted)
  bool solved = false;
  if (solver == LinearSolver::Multigrid) {
    auto converged = multigridSolve(std::move(A), rhs, x, progress, multigrid, stats.iterations);
    kept = &multigrid.matrix();
    if (!converged) return converged.error();
    solved = converged.value();
  } else if (solver == LinearSolver::BiCGSTAB) {
    auto converged = ilutSolve(A, rhs, x, progress, stats.iterations);
    if (!converged) return converged.error();
    solved = converged.value();
  }
  if (!solved) {
    stats.used = LinearSolver::SparseLU;
    if (!directSolve(*kept, rhs, x)) {
      std::fill(x.begin(), x.end(), 0.0);
      stats.residual = std::numeric_limits<double>::infinity();
      return stats;
    }
  }
  stats.residual = relativeResidual(*kept, rhs, x);
  return stats;
}

Expected<LinearSolver> parseLinearSolver(const std::string& name) {
  return parseName(kLinearSolverNames, name, "solver");
}

}  // namespace straightest
