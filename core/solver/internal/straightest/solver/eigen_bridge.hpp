// eigen_bridge.hpp — a CsrMatrix as Eigen's sparse matrix, for the solvers that hand a matrix to one
// of Eigen's factorizations (the multigrid's coarsest level, the LU and ILUT backends, SLIM's Cholesky),
// and the two-column solve through one. Internal to
// the solver sources: no public header includes Eigen.
#pragma once
#include <Eigen/Sparse>
#include <vector>

#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

inline Eigen::SparseMatrix<double> toEigen(const CsrMatrix& a) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(a.col.size());
  for (int32_t r = 0; r < a.rows; ++r)
    for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) t.emplace_back(r, a.col[k], a.value[k]);
  Eigen::SparseMatrix<double> m(a.rows, a.cols);
  m.setFromTriplets(t.begin(), t.end());  // sums repeated entries, as CsrMatrix means them
  return m;
}

/// x = A⁻¹ rhs for both columns at once, u and v interleaved (rhs[2r], rhs[2r + 1]) as the solvers
/// store them, through any factorization of A with Eigen's solve().
template <class Factorization>
void solveInterleaved(const Factorization& factor, const std::vector<double>& rhs, std::vector<double>& x) {
  const Eigen::Index n = static_cast<Eigen::Index>(rhs.size() / 2);
  Eigen::MatrixX2d b(n, 2);
  for (Eigen::Index r = 0; r < n; ++r) b.row(r) << rhs[2 * r], rhs[2 * r + 1];
  const Eigen::MatrixX2d solution = factor.solve(b);
  for (Eigen::Index r = 0; r < n; ++r) {
    x[2 * r] = solution(r, 0);
    x[2 * r + 1] = solution(r, 1);
  }
}

}  // namespace straightest
