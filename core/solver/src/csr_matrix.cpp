// csr_matrix.cpp — the compressed-row kernels: shape check, two-column product, transpose, matrix
// product, row sorting, diagonal. The row-wise ones (two-column product, matrix product, sorting, diagonal) run on all
// threads (row_chunks.hpp): each row is computed as on one thread, so results do not depend on the count.
#include "straightest/solver/csr_matrix.hpp"

#include "row_accumulator.hpp"
#include "row_chunks.hpp"
#include "row_product.hpp"

namespace straightest {

void CsrMatrix::multiply2(const double* x, double* y) const {
  // Rows are independent: chunks of them run on all threads, each row summed as on one.
  const detail::CsrRows rows(*this);
  detail::forRowChunks(static_cast<size_t>(this->rows), [=](size_t begin, size_t end) {
    for (size_t r = begin; r < end; ++r) detail::rowTimesTwoColumns(rows, r, x, y);
  });
}

bool wellFormed(const CsrMatrix& m) {
  if (m.rows < 0 || m.cols < 0 || m.start.size() != static_cast<size_t>(m.rows) + 1 || m.start.front() != 0 ||
      m.start.back() < 0 || static_cast<size_t>(m.start.back()) != m.col.size() || m.value.size() != m.col.size())
    return false;
  for (int32_t r = 0; r < m.rows; ++r)
    if (m.start[r + 1] < m.start[r]) return false;
  for (int32_t c : m.col)
    if (c < 0 || c >= m.cols) return false;
  return true;
}

CsrMatrix transpose(const CsrMatrix& m) {
  CsrMatrix t;
  t.rows = m.cols;
  t.cols = m.rows;
  t.start.assign(static_cast<size_t>(t.rows) + 1, 0);
  for (int32_t c : m.col) ++t.start[c + 1];
  for (int32_t r = 0; r < t.rows; ++r) t.start[r + 1] += t.start[r];
  t.col.resize(m.col.size());
  t.value.resize(m.value.size());
  std::vector<int32_t> next(t.start.begin(), t.start.end() - 1);
  for (int32_t r = 0; r < m.rows; ++r)
    for (int32_t k = m.start[r]; k < m.start[r + 1]; ++k) {
      const int32_t at = next[m.col[k]]++;
      t.col[at] = r;
      t.value[at] = m.value[k];
    }
  return t;
}

namespace {

/// v times row j of m, into acc.
inline void addScaledRow(const CsrMatrix& m, int32_t j, double v, RowAccumulator& acc) {
  for (int32_t k = m.start[j]; k < m.start[j + 1]; ++k) acc.add(m.col[k], v * m.value[k]);
}

/// Row r of a · b into acc: the entries of b's rows, scaled by a's row r, in a's and then b's order.
inline void addRowProduct(const CsrMatrix& a, const CsrMatrix& b, int32_t r, RowAccumulator& acc) {
  for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) addScaledRow(b, a.col[k], a.value[k], acc);
}

}  // namespace

CsrMatrix multiply(const CsrMatrix& a, const CsrMatrix& b, size_t expectedNonZeros) {
  return buildRows(a.rows, b.cols, expectedNonZeros, false,
                   [&a, &b](int32_t r, RowAccumulator& acc) { addRowProduct(a, b, r, acc); });
}

RowPieces multiplyInPieces(const CsrMatrix& a, const CsrMatrix& b, size_t expectedNonZeros) {
  return buildRowPieces(a.rows, b.cols, expectedNonZeros, false,
                        [&a, &b](int32_t r, RowAccumulator& acc) { addRowProduct(a, b, r, acc); });
}

CsrMatrix multiply(const CsrMatrix& a, const RowPieces& b, size_t expectedNonZeros) {
  const std::vector<int32_t>& first = b.first;
  return buildRows(a.rows, b.cols, expectedNonZeros, false, [&](int32_t r, RowAccumulator& acc) {
    // The part that holds row j: found by stepping from the previous entry's, as a's rows usually
    // list nearby columns in ascending order (a restriction's rows are sorted).
    size_t p = 0;
    for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) {
      const int32_t j = a.col[k];
      while (j >= first[p + 1]) ++p;
      while (j < first[p]) --p;
      addScaledRow(b.parts[p], j - first[p], a.value[k], acc);
    }
  });
}

std::vector<int32_t> sortRows(CsrMatrix& m) {
  // Insertion sort: rows are short (a one ring, or a coarse row of a few dozen entries).
  std::vector<int32_t> split(m.rows);
  detail::forRowChunks(static_cast<size_t>(m.rows), [&m, &split](size_t begin, size_t end) {
    for (size_t r = begin; r < end; ++r) {
      const int32_t b = m.start[r], e = m.start[r + 1];
      for (int32_t k = b + 1; k < e; ++k) {
        const int32_t c = m.col[k];
        const double v = m.value[k];
        int32_t q = k;
        for (; q > b && m.col[q - 1] > c; --q) {
          m.col[q] = m.col[q - 1];
          m.value[q] = m.value[q - 1];
        }
        m.col[q] = c;
        m.value[q] = v;
      }
      int32_t k = b;
      while (k < e && m.col[k] < static_cast<int32_t>(r)) ++k;
      split[r] = k;
    }
  });
  return split;
}

std::vector<double> diagonal(const CsrMatrix& m) {
  std::vector<double> d(m.rows, 0.0);
  detail::forRowChunks(static_cast<size_t>(m.rows), [&m, &d](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      for (int32_t k = m.start[i]; k < m.start[i + 1]; ++k)
        if (m.col[k] == static_cast<int32_t>(i)) d[i] += m.value[k];
  });
  return d;
}

}  // namespace straightest
