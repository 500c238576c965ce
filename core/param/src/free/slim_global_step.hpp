// slim_global_step.hpp — the global step of SLIM (Rabinovich et al. 2017) for a map of a disk: given
// each face's target rotation R_f and weight M_f (a symmetric 2 × 2 matrix in the face's 3D frame, from
// the local step), the map minimizing
//     Σ_f A_f (∇u_f − R_f row 0)ᵀ M_f (∇u_f − R_f row 0) + the same for v
// over every vertex, boundary included. Because M_f acts in the face's frame (SLIM's weight multiplies J
// on the right, not the left: the same value and gradient at the current map, see free_boundary.hpp),
// u and v share one symmetric matrix and are solved together. A tiny proximal term toward the current
// map (1e-8 × the mean diagonal) pins the translation, the energy's only null direction.
//
// Solver: below kDirectSize vertices, Eigen's sparse Cholesky (LDLᵀ), the ordering computed once and
// the factorization renewed each iteration. Above, conjugate
// gradients from the current map, preconditioned by one smoothed-aggregation multigrid V-cycle
// (multigrid.hpp; symmetric, as conjugate gradients need); the hierarchy is kept across iterations,
// whose weights change little, and rebuilt when a solve needs more than kStaleIterations. Cholesky is
// the fallback when conjugate gradients do not converge. Why both: a factorization is immune to the
// ill-conditioning of very distorted maps but fills in, so above kDirectSize a multigrid-preconditioned
// solve is cheaper than a factorization.
// Private to the free-boundary refinement.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "straightest/mesh/trimesh.hpp"
#include "straightest/solver/csr_matrix.hpp"
#include "straightest/solver/multigrid.hpp"
#include "symmetric_dirichlet.hpp"

namespace straightest {

class SlimGlobalStep {
 public:
  static constexpr int32_t kDirectSize = 30000;
  static constexpr double kProximalRel = 1e-8;     // × the mean diagonal
  static constexpr double kSolveReduction = 1e-6;  // conjugate gradients: residual reduction from the warm start
  static constexpr int kStaleIterations = 25;      // then rebuild the multigrid for the next solve
  static constexpr int kMaxIterations = 200;       // then rebuild it now, and at last factorize

  /// `directSize`: meshes with at most this many vertices are solved by factorization.
  explicit SlimGlobalStep(const TriMesh& mesh, int32_t directSize = kDirectSize);
  ~SlimGlobalStep();

  /// The next map from `uv` (also the iterative solve's start) and each face's weight M_f and target
  /// rotation R_f (faces of zero area in `gradients` are left out). False when no solver succeeds.
  bool solve(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
             const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv, std::vector<Vec2>& next);

  /// Conjugate-gradient iterations of the last solve (0 for a direct one).
  int lastIterations() const { return lastIterations_; }

 private:
  int32_t slot(int32_t row, int32_t col) const;
  void assemble(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
                const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv);
  int conjugateGradients(std::vector<double>& x) const;
  bool directSolve(std::vector<double>& x);

  const TriMesh& mesh_;
  int32_t n_, directSize_;
  CsrMatrix matrix_;
  std::vector<double> rhs_;  // u and v interleaved, as CsrMatrix::multiply2 reads them
  std::vector<size_t> slots_;
  std::vector<int32_t> diagonal_;
  AggregationMultigrid multigrid_;
  bool preconditionerCurrent_ = false;  // the hierarchy was built from a recent enough matrix
  int lastIterations_ = 0;
  struct Cholesky;  // Eigen's factorization, its pattern analysed once
  std::unique_ptr<Cholesky> cholesky_;
};

}  // namespace straightest
