// multigrid.hpp — a smoothed-aggregation algebraic multigrid hierarchy, applied as one V-cycle to two
// interleaved right-hand sides: the preconditioner of the two-column Krylov solver (krylov.hpp).
// The systems are I − W: M-matrices, one row per interior vertex, W row-stochastic, not symmetric for
// shape-preserving or mean-value weights.
//
// Why: Eigen's direct solvers fill in badly on million-vertex meshes (SparseLU with COLAMD takes over a
// minute at 1M vertices) and unpreconditioned Krylov methods need thousands of iterations; a multigrid V-cycle
// makes BiCGSTAB converge in about ten iterations at any size.
//
// Setup: strength of connection |a_ij| >= kStrength·sqrt(|a_ii a_jj|); greedy aggregation (roots whose
// strong neighbours are all free, then attach the rest); tentative prolongator = piecewise constants
// per aggregate, smoothed by one damped Jacobi step (ω = 2/3: it needed the fewest iterations of the
// values tried); A_c = Pᵀ A P by two row-wise sparse products; down to at
// most kCoarseSize unknowns, solved exactly by a sparse LU (Eigen's, hidden in the source). R = Pᵀ is
// kept (the transpose the Galerkin product needs anyway): the cycle restricts by R's rows, each coarse
// row on its own, so the restriction runs on all threads (~12 bytes per entry of P). Cycle: V(1, 1)
// with Gauss–Seidel smoothing, forward before the coarse correction and backward after it (a fixed
// linear operator, as a Krylov preconditioner must be); at 1M vertices it beat V(2, 2) Gauss–Seidel
// and V(2, 2) damped Jacobi on time to solution. The cycle reads A, P and R in single precision (its
// vectors stay double): fewer bytes per entry to wait for, with the same iteration count. (The cycle is bound by
// latency — the sweeps' chain of dependent rows and scattered reads — not by bandwidth: see bench/bench_bandwidth.cpp.)
// The Krylov solver's products use A in double precision.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "straightest/base/progress.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

class AggregationMultigrid {
 public:
  static constexpr double kStrength = 0.08;
  static constexpr int kCoarseSize = 400;

  enum class Smoother { Jacobi, GaussSeidel };
  struct Options {
    Smoother smoother = Smoother::GaussSeidel;
    int preSweeps = 1, postSweeps = 1;
  };

  AggregationMultigrid();
  explicit AggregationMultigrid(Options options);
  ~AggregationMultigrid();
  AggregationMultigrid(AggregationMultigrid&&) noexcept;
  AggregationMultigrid& operator=(AggregationMultigrid&&) noexcept;

  /// Builds the hierarchy for a square A, which it keeps (matrix(), sorted by column within rows).
  /// Reports the fraction of the setup done after each level as stage "solve"; a progress that says
  /// stop gives a Cancelled error. Returns false when A cannot be handled (a zero or non-finite
  /// diagonal entry, a failed coarse factorization): the caller solves otherwise. ok() tells the same.
  Expected<bool> compute(CsrMatrix A, const Progress& progress = {});
  bool ok() const;
  /// The finest level's matrix: the A given to compute (valid after any compute, even a failed one).
  const CsrMatrix& matrix() const;

  /// One V-cycle for two interleaved right-hand sides: x ≈ A⁻¹ b (x and b have 2·rows entries and
  /// must not alias). Uses internal work space: one apply at a time per object.
  void apply(const double* b, double* x) const;

  int levels() const;
  /// Unknowns per level, finest first.
  std::vector<int32_t> sizes() const;

 private:
  struct Hierarchy;  // the levels and the coarsest level's factorization (Eigen)
  Options options_;
  std::unique_ptr<Hierarchy> hierarchy_;
};

}  // namespace straightest
