// eigen_bridge.hpp — a CsrMatrix as Eigen's sparse matrix, for the solvers that hand a matrix to one
// of Eigen's factorizations (the multigrid's coarsest level, the LU and ILUT backends). Internal to
// the solver sources: no public header includes Eigen.
#pragma once
#include <Eigen/Sparse>
#include <vector>

#include "straightest/csr_matrix.hpp"

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

}  // namespace straightest
