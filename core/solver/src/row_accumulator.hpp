// row_accumulator.hpp — gathers one sparse row at a time for the CSR products (Gustavson's sparse
// accumulator): a dense slot per column (−1 = empty) and the list of used columns, so a row of any
// length costs only its own entries; and buildRows, which builds a matrix's rows with it on all
// threads. Internal to the solver sources.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "row_chunks.hpp"
#include "straightest/base/parallel_for.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

// Fixed-size buffers and no push_back in add(): a possible reallocation call per entry kept the
// compilers (and WebAssembly in particular) from holding the pointers in registers.
class RowAccumulator {
 public:
  explicit RowAccumulator(int32_t cols) : slot_(cols, -1), cols_(cols), values_(cols) {}
  void add(int32_t c, double v) {
    const int32_t s = slot_[c];
    if (s < 0) {
      slot_[c] = used_;
      cols_[used_] = c;
      values_[used_++] = v;
    } else {
      values_[s] += v;
    }
  }
  /// Appends the row to m (dropping exact zeros when asked) and clears the accumulator. The row is
  /// compacted in place and appended as two ranges: growing m's arrays by resize() instead zero-filled
  /// the new entries before they were overwritten, a call per row (in WebAssembly a call and a loop per
  /// row).
  void flushInto(CsrMatrix& m, bool dropZeros) {
    int32_t kept = 0;
    for (int32_t k = 0; k < used_; ++k) {
      slot_[cols_[k]] = -1;
      if (dropZeros && values_[k] == 0) continue;
      cols_[kept] = cols_[k];
      values_[kept++] = values_[k];
    }
    m.col.insert(m.col.end(), cols_.data(), cols_.data() + kept);
    m.value.insert(m.value.end(), values_.data(), values_.data() + kept);
    used_ = 0;
    m.start.push_back(static_cast<int32_t>(m.col.size()));
  }

 private:
  std::vector<int32_t> slot_, cols_;
  std::vector<double> values_;
  int32_t used_ = 0;
};

/// A matrix's rows built in pieces (detail::rowPieces), before they are copied after one another: part p
/// holds rows first[p] … first[p + 1] − 1, numbered from 0 in it. A product whose right factor is used
/// only by rows can read the pieces where they are (multiply below) instead of a copy of them all.
struct RowPieces {
  int32_t rows = 0, cols = 0;
  std::vector<int32_t> first;  // every part's first row, then rows
  std::vector<CsrMatrix> parts;
};

/// The rows × cols matrix whose row r is what row(r, acc) adds to the accumulator (exact zeros dropped when
/// asked), in pieces: detail::rowPieces (fixed by the row count) built on all threads, each with its own
/// accumulator into its own arrays. expectedNonZeros: a reservation for the whole matrix (0: none).
template <class Row>
RowPieces buildRowPieces(int32_t rows, int32_t cols, size_t expectedNonZeros, bool dropZeros, const Row& row) {
  RowPieces out;
  out.rows = rows;
  out.cols = cols;
  out.first = detail::rowPieces(rows);
  const std::vector<int32_t>& first = out.first;
  const auto pieces = static_cast<int32_t>(first.size() - 1);
  // The pieces' arrays are reserved here, on the calling thread: a block a worker thread allocates
  // comes from that thread's own malloc arena, which gives its pages back when the block is freed.
  // Reserved by the workers, every repeated multigrid setup faulted its pages in again.
  std::vector<CsrMatrix>& parts = out.parts;
  parts.resize(pieces);
  for (int32_t p = 0; p < pieces; ++p) {
    parts[p].rows = first[p + 1] - first[p];
    parts[p].cols = cols;
    parts[p].start.reserve(static_cast<size_t>(first[p + 1] - first[p]) + 1);
    parts[p].col.reserve(expectedNonZeros / pieces);
    parts[p].value.reserve(expectedNonZeros / pieces);
  }
  detail::parallelFor(static_cast<std::size_t>(pieces), 1, [&](std::size_t p, std::size_t, std::size_t) {
    CsrMatrix& part = parts[p];
    RowAccumulator acc(cols);
    for (int32_t r = first[p]; r < first[p + 1]; ++r) {
      row(r, acc);
      acc.flushInto(part, dropZeros);
    }
  });
  return out;
}

/// The pieces as one matrix: entry for entry the matrix one pass over the rows gives, for any thread
/// count. One piece after another, each freed once copied (reserve and insert: no zero-fill of entries
/// that are overwritten at once).
inline CsrMatrix joinRowPieces(RowPieces pieces) {
  if (pieces.parts.size() == 1) {
    CsrMatrix m = std::move(pieces.parts[0]);
    m.rows = pieces.rows;
    m.cols = pieces.cols;
    return m;
  }
  size_t total = 0;
  for (const CsrMatrix& part : pieces.parts) total += part.col.size();
  CsrMatrix m;
  m.rows = pieces.rows;
  m.cols = pieces.cols;
  m.start.reserve(static_cast<size_t>(pieces.rows) + 1);
  m.col.reserve(total);
  m.value.reserve(total);
  for (CsrMatrix& part : pieces.parts) {
    const auto shift = static_cast<int32_t>(m.col.size());
    for (size_t r = 1; r < part.start.size(); ++r) m.start.push_back(part.start[r] + shift);
    m.col.insert(m.col.end(), part.col.begin(), part.col.end());
    m.value.insert(m.value.end(), part.value.begin(), part.value.end());
    part = CsrMatrix();
  }
  return m;
}

/// The matrix whose row r is what row(r, acc) adds to the accumulator: buildRowPieces, joined.
template <class Row>
CsrMatrix buildRows(int32_t rows, int32_t cols, size_t expectedNonZeros, bool dropZeros, const Row& row) {
  return joinRowPieces(buildRowPieces(rows, cols, expectedNonZeros, dropZeros, row));
}

/// a · b with b left in its pieces (defined in csr_matrix.cpp): the same entries, in the same order, as
/// multiply(a, joinRowPieces(b)).
CsrMatrix multiply(const CsrMatrix& a, const RowPieces& b, size_t expectedNonZeros);

/// a · b by rows, left in its pieces (defined in csr_matrix.cpp).
RowPieces multiplyInPieces(const CsrMatrix& a, const CsrMatrix& b, size_t expectedNonZeros);

}  // namespace straightest
