// row_accumulator.hpp — gathers one sparse row at a time for the CSR products (Gustavson's sparse
// accumulator): a dense slot per column (−1 = empty) and the list of used columns, so a row of any
// length costs only its own entries. Internal to the solver sources.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/csr_matrix.hpp"

namespace straightest {

// Fixed-size buffers and no push_back in add(): a possible reallocation call per entry kept the
// compilers (and WebAssembly in particular, 4× slower than native) from holding the pointers in
// registers.
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
  /// Appends the row to m (dropping exact zeros when asked) and clears the accumulator.
  void flushInto(CsrMatrix& m, bool dropZeros) {
    size_t at = m.col.size();
    m.col.resize(at + used_);
    m.value.resize(at + used_);
    for (int32_t k = 0; k < used_; ++k) {
      slot_[cols_[k]] = -1;
      if (dropZeros && values_[k] == 0) continue;
      m.col[at] = cols_[k];
      m.value[at++] = values_[k];
    }
    m.col.resize(at);
    m.value.resize(at);
    used_ = 0;
    m.start.push_back(static_cast<int32_t>(at));
  }

 private:
  std::vector<int32_t> slot_, cols_;
  std::vector<double> values_;
  int32_t used_ = 0;
};

}  // namespace straightest
