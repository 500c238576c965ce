// texel_mask.hpp — a rectangle of texels as rows of 64-bit words (bit i of word k is texel 64k + i), so that
// the packer tests and sets 64 texels per instruction.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace straightest::atlas_detail {

class TexelMask {
 public:
  TexelMask() = default;
  // One spare zero word ends every row, so reading 64 bits from any texel of a row needs no bounds test.
  TexelMask(int32_t width, int32_t height)
      : width_(width),
        height_(height),
        wordsPerRow_((width + 63) / 64 + 1),
        words_(static_cast<size_t>(wordsPerRow_) * static_cast<size_t>(height), 0) {}

  int32_t width() const { return width_; }
  int32_t height() const { return height_; }
  int32_t wordsPerRow() const { return wordsPerRow_; }
  uint64_t* row(int32_t y) { return words_.data() + static_cast<size_t>(y) * wordsPerRow_; }
  const uint64_t* row(int32_t y) const { return words_.data() + static_cast<size_t>(y) * wordsPerRow_; }

  bool test(int32_t x, int32_t y) const { return (row(y)[x >> 6] >> (x & 63)) & 1; }

  /// Sets (value true) or clears texels x0..x1 (inclusive) of row y; the span is clipped to the mask.
  void assignSpan(int32_t y, int32_t x0, int32_t x1, bool value) {
    if (y < 0 || y >= height_) return;
    x0 = std::max(x0, 0);
    x1 = std::min(x1, width_ - 1);
    if (x0 > x1) return;
    uint64_t* words = row(y);
    const int32_t first = x0 >> 6, last = x1 >> 6;
    for (int32_t k = first; k <= last; ++k) {
      const int32_t lo = k == first ? (x0 & 63) : 0, hi = k == last ? (x1 & 63) : 63;
      const uint64_t bits = (~uint64_t{0} >> (63 - hi)) & (~uint64_t{0} << lo);
      words[k] = value ? (words[k] | bits) : (words[k] & ~bits);
    }
  }

  /// The first texel at or after x in row y whose bit equals `value`; width() when there is none.
  int32_t nextWithBit(int32_t y, int32_t x, bool value) const {
    const uint64_t* words = row(y);
    while (x < width_) {
      const uint64_t word = value ? words[x >> 6] : ~words[x >> 6];
      const uint64_t fromX = word >> (x & 63);
      if (fromX != 0) return std::min(width_, x + __builtin_ctzll(fromX));
      x = (x | 63) + 1;
    }
    return width_;
  }

  /// The 64 texels of row y starting at texel x (0 past the row's end).
  uint64_t bitsFrom(int32_t y, int32_t x) const { return bitsFromWords(row(y), wordsPerRow_, x); }

  /// The 64 bits starting at bit `x` of `words` (count words; bits past the end read 0).
  static uint64_t bitsFromWords(const uint64_t* words, int32_t count, int32_t x) {
    const int32_t k = x >> 6, shift = x & 63;
    if (k >= count) return 0;
    const uint64_t low = words[k] >> shift;
    if (shift == 0 || k + 1 >= count) return low;
    return low | (words[k + 1] << (64 - shift));
  }

 private:
  int32_t width_ = 0, height_ = 0, wordsPerRow_ = 1;
  std::vector<uint64_t> words_;
};

/// The longest run of set bits among the first `width` bits of `words` (the first such run's start in `start`).
inline int32_t longestRunOfBits(const uint64_t* words, int32_t width, int32_t* start = nullptr) {
  int32_t longest = 0, current = 0;
  auto endRun = [&](int32_t end) {
    if (current > longest && start) *start = end - current;
    longest = std::max(longest, current);
    current = 0;
  };
  for (int32_t k = 0; 64 * k < width; ++k) {
    const int32_t bits = std::min(64, width - 64 * k);
    const uint64_t word = bits < 64 ? words[k] & ((uint64_t{1} << bits) - 1) : words[k];
    if (word == ~uint64_t{0}) {
      current += 64;
      continue;
    }
    for (int32_t at = 0; at < bits;) {
      const uint64_t rest = word >> at;
      if (rest & 1) {
        const int32_t ones = __builtin_ctzll(~rest);  // rest is not all ones: word is not
        current += ones;
        at += ones;
      } else {
        endRun(64 * k + at);
        if (rest == 0) break;
        at += __builtin_ctzll(rest);
      }
    }
  }
  endRun(width);
  return longest;
}

}  // namespace straightest::atlas_detail
