// atlas_occupancy.hpp — the atlas's free texels: where a chart mask fits first (bottom-left), and the
// claiming of a placed chart together with its padding.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "chart_raster.hpp"
#include "texel_mask.hpp"

namespace straightest::atlas_detail {

struct TexelPosition {
  int32_t x = 0, y = 0;
};

/// Words [first, last] of a row (inclusive).
struct WordRange {
  int32_t first = 0, last = 0;
};

class AtlasOccupancy {
 public:
  /// An atlas of width × height texels whose outer `border` texels are never free; charts are kept
  /// `padding` texels apart (see claim).
  AtlasOccupancy(int32_t width, int32_t height, int32_t border, double padding);

  /// The lowest row, then the leftmost column, at which `mask` meets only free texels, considering mask
  /// positions whose bottom row is at most `highestRow`; nothing when it fits nowhere.
  std::optional<TexelPosition> firstFit(const ChartMask& mask, int32_t highestRow) const;

  /// Marks the mask's texels at `position`, dilated by the padding, as taken. The dilation adds every
  /// texel whose square is closer than `padding` to a set texel's square (squares dx, dy apart are
  /// max(|dx| − 1, 0), max(|dy| − 1, 0) apart along the axes), so a later chart whose own texels are all
  /// free is at least `padding` away from this one, continuous geometry included.
  void claim(const ChartMask& mask, TexelPosition position);

  int32_t width() const { return freeTexels().width(); }
  int32_t height() const { return freeTexels().height(); }

  /// The levels of free spans kept per row: spans of 1 (the free texels themselves), 4, 16 and 64 texels.
  static constexpr int kLevels = 4;

 private:
  bool runsFitAtRow(const ChartMask& mask, int32_t y) const;
  void prepareSpanTests(const ChartMask& mask) const;
  bool wordsThatMayFit(int32_t y, int32_t lastX) const;
  std::optional<int32_t> leftmostFitInRow(int32_t y, int32_t lastX) const;
  uint64_t blockColumnsFree(int32_t y, int32_t word) const;
  void updateRow(int32_t y, WordRange changed);
  void updateBlocks(int32_t firstRow, int32_t lastRow, WordRange changed);
  int32_t lowestRowForBlocks(const ChartMask& mask) const;
  bool blocksFitAtRow(const ChartMask& mask, int32_t y) const;
  void updateSpans(int32_t y, WordRange changed);
  // The free texels: the spans of 1 (a function, not a reference member, so that an occupancy copies).
  TexelMask& freeTexels() { return spans_[0]; }
  const TexelMask& freeTexels() const { return spans_[0]; }

  // spans_[level] bit p: the 4^level texels from p are all free, kept per row so that any run is tested at 64
  // columns at once with at most four shifted words.
  TexelMask spans_[kLevels];
  // wordSummary_[level], summaryWords_ per row: bit k says word k of the row's spans has a bit set, so that the
  // words of a row where a mask cannot start are ruled out 64 at a time.
  std::vector<uint64_t> wordSummary_[kLevels];
  int32_t summaryWords_ = 0;
  std::vector<int32_t> longestFreeRun_;  // per atlas row: rows that cannot hold a mask row are skipped
  // Per block height in kBlockRows and atlas row y, the longest run of columns free in rows y … y + height − 1
  // (0 where the block would pass the top), tested against the mask's blocks; the free texels of every
  // 4 rows from y kept as a bitmap, so that a block of 16 rows is four of them.
  std::vector<int32_t> longestFreeBlockRun_[2];
  TexelMask freeInFourRows_;
  // Per block height and run length, a row at or below the lowest row whose free block run is that long
  // (scratch of firstFit, raised as it finds rows that are too full).
  mutable std::vector<int32_t> lowestBlockRow_[2];
  // The free texels of every 16 rows from y: a place must find the mask's block of 16 rows free there, tested
  // at a few of the block's columns on 64 columns at once before the mask's own runs (blockColumns_, scratch
  // of firstFit, mask coordinates).
  TexelMask freeInSixteenRows_;
  mutable std::vector<int32_t> blockColumns_;
  mutable int32_t blockRow_ = 0;
  std::vector<int32_t> dilationReach_;  // per |dy| in 0..reach: how far the padding reaches along x
  // A mask row's run of L texels is free when the free spans of the largest length s ≤ L (1, 4, 16 or 64)
  // that tile it start free; the mask being placed, as such tests (scratch of firstFit).
  struct SpanTest {
    int32_t level, row, from;
  };
  mutable std::vector<SpanTest> spanTests_;
  mutable std::vector<uint64_t> candidateWords_;  // scratch of wordsThatMayFit: bit k, word k may hold a fit
  mutable size_t lastEmptyingTest_ = 0;
};

}  // namespace straightest::atlas_detail
