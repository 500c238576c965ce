// krylov.hpp — right-preconditioned BiCGSTAB (van der Vorst) for A X = B with two right-hand sides
// (a parameterization's u and v) whose recurrences run side by side: one pass over A and one
// preconditioner application per step serve both columns. Vectors hold the columns interleaved
// (entry 2i is row i's first column, 2i+1 its second), as CsrMatrix::multiply2 reads them.
#pragma once
#include <functional>
#include <vector>

#include "straightest/base/progress.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

/// x ≈ M⁻¹ b for two interleaved columns (x and b do not alias): a fixed linear operator, e.g. one
/// multigrid V-cycle (AggregationMultigrid::apply).
using TwoColumnPreconditioner = std::function<void(const double* b, double* x)>;

/// Result of solveTwoColumns.
struct KrylovStats {
  int iterations = 0;
  double relativeResidual[2] = {0, 0};  // |b − A x| / |b| per column, from the recurrence
  bool converged = false;
};

/// Solves A X = B; x holds the initial guess on entry. A column that has converged stops changing; a
/// column whose half-step residual s is small enough stops there (x += α y) without the step's second
/// preconditioner application. Stops when both columns reach |r| ≤ tolerance·|b| (an all-zero b
/// column gives x = 0), after maxIterations, or on breakdown (non-finite values): converged tells.
/// Reports after each iteration, as stage "solve", the fraction of the way from the initial residual
/// to the tolerance (by logarithm, never going back); a progress that says stop gives a Cancelled
/// error.
Expected<KrylovStats> solveTwoColumns(const CsrMatrix& A, const TwoColumnPreconditioner& M,
                                      const std::vector<double>& b, std::vector<double>& x, double tolerance,
                                      int maxIterations, const Progress& progress = {});

}  // namespace straightest
