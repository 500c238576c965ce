// csr_matrix.hpp — the library's sparse matrix: compressed rows, and the kernels the solvers need
// (the two-column product, transpose, the product of two matrices, row sorting, the diagonal).
//
// Why not Eigen's: the solve is bound by memory traffic, so vectors hold the two right-hand sides of
// a parameterization (u and v) interleaved — entry 2i is row i's u, 2i+1 its v — and every sweep over
// a matrix serves both columns (multiply2). The type is also the one the interior weights are built
// in, so nothing is copied between assembly and solve. Eigen stays inside the solvers' sources.
#pragma once
#include <cstddef>
#include <cstdint>
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
};

/// True when the arrays describe a rows × cols matrix: start runs from 0 to nonZeros() without going
/// back, col and value have one entry per non-zero, and every column lies in [0, cols).
bool wellFormed(const CsrMatrix& a);

/// Aᵀ (rows of the result in column order of A, so every row comes out sorted).
CsrMatrix transpose(const CsrMatrix& a);

/// a · b, row by row (Gustavson); repeated columns of a row are summed. expectedNonZeros only sizes
/// the first allocation.
CsrMatrix multiply(const CsrMatrix& a, const CsrMatrix& b, size_t expectedNonZeros = 0);

/// Sorts every row's entries by column (entries of equal column keep their order) and returns, per
/// row, the index of its first entry with column ≥ row: below it lies the strict lower triangle.
std::vector<int32_t> sortRows(CsrMatrix& a);

/// Per row, the sum of its entries on the diagonal (0 where there is none), summed in storage order.
std::vector<double> diagonal(const CsrMatrix& a);

}  // namespace straightest
