// disjoint_sets.hpp — union–find over 0..n−1 with path halving: which items a run of joins has connected
// (the cut graph's dual spanning tree, the atlas check's charts).
#pragma once
#include <cstdint>
#include <numeric>
#include <vector>

namespace straightest {

class DisjointSets {
 public:
  explicit DisjointSets(int32_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  /// The representative of x's set.
  int32_t find(int32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  /// Joins the sets of a and b; false when they were one set already.
  bool unite(int32_t a, int32_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

 private:
  std::vector<int32_t> parent_;
};

}  // namespace straightest
