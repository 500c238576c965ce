// multigrid.hpp — a smoothed-aggregation algebraic multigrid preconditioner and a BiCGSTAB that runs the
// two coordinate systems of a parameterization (u and v: one matrix, two right-hand sides) in lockstep.
// The systems are I − W: M-matrices, one row per interior vertex, W row-stochastic, not symmetric for
// shape-preserving or mean-value weights.
//
// Why: Eigen's direct solvers fill in badly on million-vertex meshes (SparseLU with COLAMD: ~85 s for
// 1M vertices) and unpreconditioned Krylov methods need thousands of iterations; a multigrid V-cycle
// makes BiCGSTAB converge in about ten iterations at any size. At that point the solve is bound by
// memory traffic (every matrix entry is read a dozen times per iteration for a few flops), so the
// matrices are the library's own compressed rows (CsrMatrix) and every vector holds both right-hand
// sides interleaved (entry 2i is row i's u, 2i+1 its v): each sweep over a matrix serves both columns.
//
// Setup: strength of connection |a_ij| >= kStrength·sqrt(|a_ii a_jj|); greedy aggregation (roots whose
// strong neighbours are all free, then attach the rest); tentative prolongator = piecewise constants
// per aggregate, smoothed by one damped Jacobi step (ω = 2/3: on a 100k height field ω = 0.6 and 0.8
// took 13 and 24 iterations instead of 9); A_c = Pᵀ A P by two row-wise sparse products; down to at
// most kCoarseSize unknowns, solved exactly by SparseLU. R = Pᵀ is not kept: the cycle restricts by
// scattering through P's rows. Cycle: V(1, 1) with Gauss–Seidel smoothing, forward before the coarse
// correction and backward after it (a fixed linear operator, as a Krylov preconditioner must be);
// at 1M vertices it beat V(2, 2) Gauss–Seidel and V(2, 2) damped Jacobi on time to solution.
#pragma once
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace straightest {

/// A sparse matrix in compressed rows. Column indices within a row need not be sorted; a repeated
/// column counts as the sum of its entries.
struct CsrMatrix {
  int32_t rows = 0, cols = 0;
  std::vector<int32_t> start{0};  // row r's entries are [start[r], start[r + 1])
  std::vector<int32_t> col;
  std::vector<double> value;

  int64_t nonZeros() const { return static_cast<int64_t>(col.size()); }
  /// y = A x for two interleaved columns (x has 2·cols entries, y 2·rows).
  void multiply2(const double* x, double* y) const;
  Eigen::SparseMatrix<double> toEigen() const;
};

class AggregationMultigrid {
 public:
  static constexpr double kStrength = 0.08;
  static constexpr int kCoarseSize = 400;

  enum class Smoother { Jacobi, GaussSeidel };
  struct Options {
    Smoother smoother = Smoother::GaussSeidel;
    int preSweeps = 1, postSweeps = 1;
  };

  AggregationMultigrid() = default;
  explicit AggregationMultigrid(Options options) : options_(options) {}

  /// Builds the hierarchy for a square A, which it keeps (matrix()). `progress` (optional) is called
  /// with the fraction of the setup done after each level; returning false stops the setup (compute
  /// then returns false, ok() too). Returns false also on a zero diagonal or a failed coarse
  /// factorization.
  bool compute(CsrMatrix A, const std::function<bool(double)>& progress = {});
  bool ok() const { return ok_; }
  /// The finest level's matrix: the A given to compute.
  const CsrMatrix& matrix() const { return levels_.front().A; }

  /// One V-cycle for two interleaved right-hand sides: x ≈ A⁻¹ b (x and b have 2·rows entries and
  /// must not alias). Uses internal work space: one apply at a time per object.
  void apply(const double* b, double* x) const;

  int levels() const { return static_cast<int>(levels_.size()); }
  /// Unknowns per level, finest first.
  std::vector<int32_t> sizes() const;

 private:
  struct Level {
    CsrMatrix A;
    CsrMatrix P;                      // prolongator to this level from the next coarser one
    std::vector<int32_t> split;       // per row: first entry with column ≥ row (rows are sorted)
    std::vector<double> invDiag;
    // Work space, two entries per unknown: b and x of the coarser levels' cycles; tmp for Jacobi.
    mutable std::vector<double> b, x, tmp;
  };
  void cycle(size_t level, const double* b, double* x) const;

  Options options_;
  std::vector<Level> levels_;
  std::shared_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> coarse_;
  mutable Eigen::MatrixXd coarseRhs_;
  bool ok_ = false;
};

/// Result of solveTwoColumns.
struct KrylovStats {
  int iterations = 0;
  double relativeResidual[2] = {0, 0};  // |b − A x| / |b| per column, from the recurrence
  bool converged = false;
  bool cancelled = false;
};

/// Right-preconditioned BiCGSTAB (van der Vorst) for A X = B with two interleaved columns, the
/// columns' recurrences run side by side: one pass over A and one V-cycle per step serve both. A
/// column that has converged stops changing; a column whose half-step residual s is small enough
/// stops there (x += α y) without the step's second V-cycle. x holds the initial guess on entry. `onIteration`
/// (optional) gets the iteration count and the larger of the two relative residuals after each
/// iteration; returning false cancels. Stops when both columns reach |r| ≤ tolerance·|b| (an all-zero
/// b column gives x = 0), after maxIterations, or on breakdown (non-finite values): converged tells.
KrylovStats solveTwoColumns(const CsrMatrix& A, const AggregationMultigrid& M, const std::vector<double>& b,
                            std::vector<double>& x, double tolerance, int maxIterations,
                            const std::function<bool(int, double)>& onIteration = {});

}  // namespace straightest
