// bucket_grid.hpp — a uniform grid of buckets over a rectangle, each holding the items whose box meets it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace straightest::atlas_detail {

struct Box {
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  bool meets(const Box& o) const { return minX <= o.maxX && o.minX <= maxX && minY <= o.maxY && o.minY <= maxY; }
  Box expanded(double r) const { return {minX - r, minY - r, maxX + r, maxY + r}; }
};

/// Items are stored once per cell their (closed) box meets, cells in row-major order (compressed rows).
class BucketGrid {
 public:
  struct CellRange {
    int64_t x0, y0, x1, y1;
  };

  /// Cells of side `cell` over `bounds`; boxOf(i) is item i's box, for i < count.
  template <class BoxOf>
  BucketGrid(const Box& bounds, double cell, int64_t count, BoxOf boxOf) : bounds_(bounds), cell_(cell) {
    nx_ = std::max<int64_t>(1, static_cast<int64_t>((bounds.maxX - bounds.minX) / cell) + 1);
    ny_ = std::max<int64_t>(1, static_cast<int64_t>((bounds.maxY - bounds.minY) / cell) + 1);
    start_.assign(nx_ * ny_ + 1, 0);
    forEachItemCell(count, boxOf, [&](int64_t c, int64_t) { ++start_[c + 1]; });
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(start_.back());
    std::vector<int64_t> fill(start_.begin(), start_.end() - 1);
    forEachItemCell(count, boxOf, [&](int64_t c, int64_t i) { items_[fill[c]++] = static_cast<int32_t>(i); });
  }

  int64_t cellCount() const { return nx_ * ny_; }
  int64_t cellX(double x) const {
    return std::clamp<int64_t>(static_cast<int64_t>(std::floor((x - bounds_.minX) / cell_)), 0, nx_ - 1);
  }
  int64_t cellY(double y) const {
    return std::clamp<int64_t>(static_cast<int64_t>(std::floor((y - bounds_.minY) / cell_)), 0, ny_ - 1);
  }
  int64_t cellOf(double x, double y) const { return cellY(y) * nx_ + cellX(x); }
  CellRange cells(const Box& b) const { return {cellX(b.minX), cellY(b.minY), cellX(b.maxX), cellY(b.maxY)}; }
  const int32_t* begin(int64_t c) const { return items_.data() + start_[c]; }
  const int32_t* end(int64_t c) const { return items_.data() + start_[c + 1]; }

 private:
  template <class BoxOf, class Visit>
  void forEachItemCell(int64_t count, BoxOf& boxOf, Visit visit) const {
    for (int64_t i = 0; i < count; ++i) {
      const CellRange r = cells(boxOf(i));
      for (int64_t y = r.y0; y <= r.y1; ++y)
        for (int64_t x = r.x0; x <= r.x1; ++x) visit(y * nx_ + x, i);
    }
  }

  Box bounds_;
  double cell_;
  int64_t nx_ = 1, ny_ = 1;
  std::vector<int64_t> start_;
  std::vector<int32_t> items_;
};

}  // namespace straightest::atlas_detail
