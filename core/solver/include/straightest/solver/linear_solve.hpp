// linear_solve.hpp — one entry point for the sparse linear systems of the library: A X = B with two
// right-hand sides (a parameterization's u and v, interleaved), by the chosen backend, with the
// fallback to a direct solve when an iterative one does not converge.
//
// Backends: Multigrid (default): the two-column BiCGSTAB (krylov.hpp) preconditioned by one
// smoothed-aggregation multigrid V-cycle (multigrid.hpp), about ten iterations at any size.
// SparseLU: Eigen's direct LU (COLAMD ordering), fine below ~100k unknowns and exact. BiCGSTAB:
// Eigen's, preconditioned by incomplete LU (ILUT), one column at a time.
//
// Progress, as stage "solve": the setup (multigrid hierarchy or ILUT factorization) is the first
// kSetupShare of it, the iterations the rest (by the logarithm of the residual's fall); never going
// back. A progress that says stop gives a Cancelled error. The direct solve reports nothing.
#pragma once
#include <string>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

enum class LinearSolver { Multigrid, SparseLU, BiCGSTAB };
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<LinearSolver> kLinearSolverNames[] = {{LinearSolver::Multigrid, "multigrid"},
                                                                {LinearSolver::SparseLU, "lu"},
                                                                {LinearSolver::BiCGSTAB, "bicgstab"}};
Expected<LinearSolver> parseLinearSolver(const std::string& name);

inline constexpr double kSolveTolerance = 1e-10;  // relative residual per column, iterative backends
inline constexpr int kSolveMaxIterations = 1000;  // then the iterative backend gives up: direct solve
inline constexpr double kSetupShare = 0.2;        // of the solve stage's progress

struct LinearSolveStats {
  LinearSolver used = LinearSolver::Multigrid;  // the backend that gave x: SparseLU after a fallback
  int iterations = 0;                           // of the iterative backend (0 for a direct solve)
  double residual = 0;  // |A x − b| / |b| over both columns (|A x − b| when b = 0); +∞ if A is singular
};

/// Solves A X = B for square A and two interleaved columns: rhs and x have 2·A.rows entries, x the
/// iterative backends' initial guess on entry and the solution on return. A is taken by value (move
/// it in: the multigrid keeps it as its finest level). When every backend fails (a singular A), x is
/// all zeros and the residual +∞. A malformed matrix or sizes that do not fit are an InvalidArgument
/// error.
Expected<LinearSolveStats> solve(CsrMatrix A, const std::vector<double>& rhs, std::vector<double>& x,
                                 LinearSolver solver, const Progress& progress = {});

}  // namespace straightest
