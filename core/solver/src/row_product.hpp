// row_product.hpp (private) — one row of a compressed-row matrix times the two interleaved columns of
// x, the kernel of every two-column product (CsrMatrix::multiply2, and the Krylov solver's products
// fused with their dot products), so all of them sum each row in the same order and give the same bits.
#pragma once
#include <cstddef>
#include <cstdint>

#include "straightest/solver/csr_matrix.hpp"

namespace straightest::detail {

/// The matrix's arrays as raw pointers: taken once before a loop over rows, so the compiler keeps them
/// in registers (it could not prove that the stores into y leave the vectors' pointers alone).
struct CsrRows {
  const int32_t* start;
  const int32_t* col;
  const double* value;
  explicit CsrRows(const CsrMatrix& a) : start(a.start.data()), col(a.col.data()), value(a.value.data()) {}
};

/// y_2r, y_2r+1 = (A x)_r for both columns: Σ_k a_rk x_2k and Σ_k a_rk x_2k+1 over row r's entries in
/// order, summed in locals (y must not alias x).
inline void rowTimesTwoColumns(const CsrRows& a, std::size_t r, const double* x, double* y) {
  double s0 = 0, s1 = 0;
  for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) {
    const double v = a.value[k];
    const int32_t j = a.col[k];
    s0 += v * x[2 * j];
    s1 += v * x[2 * j + 1];
  }
  y[2 * r] = s0;
  y[2 * r + 1] = s1;
}

}  // namespace straightest::detail
