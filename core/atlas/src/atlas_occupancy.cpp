// atlas_occupancy.cpp — first-fit search on the free-texel bitmap, 64 columns per word: a mask fits at column x
// when, for each of its runs (row r, start a, length L), the atlas row y + r has L free texels from x + a, that
// is when the free spans of the largest length s ≤ L among 1, 4, 16, 64 that tile [a, a + L) all start free.
#include "atlas_occupancy.hpp"

#include <algorithm>
#include <cmath>

namespace straightest::atlas_detail {
namespace {

/// Per |dy| = 0..reach, the largest |dx| such that texel squares dx, dy apart are closer than `padding`
/// (a gap of max(|d| − 1, 0) texels along each axis); padding 0 keeps only the texel itself.
std::vector<int32_t> paddingReach(double padding) {
  if (padding <= 0) return {0};
  const int32_t reach = static_cast<int32_t>(std::ceil(padding));
  std::vector<int32_t> dxOfDy(reach + 1);
  for (int32_t dy = 0; dy <= reach; ++dy) {
    const double gapY = std::max(dy - 1, 0);
    int32_t dx = 1;  // squares one texel apart touch: always closer than a positive padding
    while (static_cast<double>(dx) * dx + gapY * gapY < padding * padding) ++dx;
    dxOfDy[dy] = dx;
  }
  return dxOfDy;
}

}  // namespace

AtlasOccupancy::AtlasOccupancy(int32_t width, int32_t height, int32_t border, double padding)
    : longestFreeRun_(height, 0), dilationReach_(paddingReach(padding)) {
  for (TexelMask& spans : spans_) spans = TexelMask(width, height);
  summaryWords_ = (freeTexels().wordsPerRow() + 63) / 64;
  for (auto& summary : wordSummary_) summary.assign(static_cast<size_t>(summaryWords_) * height, 0);
  for (int32_t y = border; y < height - border; ++y) freeTexels().assignSpan(y, border, width - border - 1, true);
  const WordRange everyWord{0, freeTexels().wordsPerRow() - 1};
  for (int32_t y = 0; y < height; ++y) updateRow(y, everyWord);
  freeInFourRows_ = TexelMask(width, height);
  freeInSixteenRows_ = TexelMask(width, height);
  for (auto& runs : longestFreeBlockRun_) runs.assign(height, 0);
  for (auto& lowest : lowestBlockRow_) lowest.assign(width + 1, 0);
  updateBlocks(0, height - 1, everyWord);
}

void AtlasOccupancy::updateBlocks(int32_t firstRow, int32_t lastRow, WordRange changed) {
  static_assert(kBlockRows[0] == 4 && kBlockRows[1] == 16, "blocks of 16 rows are four blocks of 4");
  const int32_t words = freeTexels().wordsPerRow();
  // Rows whose blocks reach into [firstRow, lastRow]: blocks of 4 first, as the blocks of 16 are made of them.
  for (int32_t y = std::max(0, firstRow - 3); y <= lastRow; ++y) {
    uint64_t* four = freeInFourRows_.row(y);
    if (y + 4 > height()) {
      std::fill(four, four + words, 0);
      longestFreeBlockRun_[0][y] = 0;
      continue;
    }
    for (int32_t k = changed.first; k <= changed.last; ++k)
      four[k] = freeTexels().row(y)[k] & freeTexels().row(y + 1)[k] & freeTexels().row(y + 2)[k] &
                freeTexels().row(y + 3)[k];
    longestFreeBlockRun_[0][y] = longestRunOfBits(four, width());
  }
  for (int32_t y = std::max(0, firstRow - 15); y <= lastRow; ++y) {
    uint64_t* sixteen = freeInSixteenRows_.row(y);
    if (y + 16 > height()) {
      std::fill(sixteen, sixteen + words, 0);
      longestFreeBlockRun_[1][y] = 0;
      continue;
    }
    for (int32_t k = changed.first; k <= changed.last; ++k)
      sixteen[k] = freeInFourRows_.row(y)[k] & freeInFourRows_.row(y + 4)[k] & freeInFourRows_.row(y + 8)[k] &
                   freeInFourRows_.row(y + 12)[k];
    longestFreeBlockRun_[1][y] = longestRunOfBits(sixteen, width());
  }
}

int32_t AtlasOccupancy::lowestRowForBlocks(const ChartMask& mask) const {
  int32_t lowest = 0;
  for (int b = 0; b < 2; ++b) {
    const BlockRun& block = mask.blocks[b];
    if (block.length == 0) continue;
    // Texels are only ever taken, so the lowest row with a free run this long only moves up.
    int32_t& row = lowestBlockRow_[b][block.length];
    while (row < height() && longestFreeBlockRun_[b][row] < block.length) ++row;
    lowest = std::max(lowest, row - block.row);
  }
  return lowest;
}

bool AtlasOccupancy::blocksFitAtRow(const ChartMask& mask, int32_t y) const {
  for (int b = 0; b < 2; ++b) {
    const BlockRun& block = mask.blocks[b];
    if (block.length > 0 && longestFreeBlockRun_[b][y + block.row] < block.length) return false;
  }
  return true;
}

void AtlasOccupancy::updateRow(int32_t y, WordRange changed) {
  int32_t longest = 0;
  for (int32_t x = freeTexels().nextWithBit(y, 0, true); x < width();) {
    const int32_t end = freeTexels().nextWithBit(y, x, false);
    longest = std::max(longest, end - x);
    x = freeTexels().nextWithBit(y, end, true);
  }
  longestFreeRun_[y] = longest;
  updateSpans(y, changed);
}

void AtlasOccupancy::updateSpans(int32_t y, WordRange changed) {
  const int32_t count = freeTexels().wordsPerRow();
  // A span's bit at p reads the free texels p … p + 63, so the words before the change's first one move too.
  const WordRange moved{std::max(changed.first - 1, 0), changed.last};
  for (int32_t level = 1, span = 1; level < kLevels; ++level, span *= 4) {
    // Spans of 4s texels from spans of s: bits p, p + s, p + 2s and p + 3s.
    const uint64_t* shorter = spans_[level - 1].row(y);
    uint64_t* words = spans_[level].row(y);
    for (int32_t k = moved.first; k <= moved.last; ++k) {
      uint64_t all = ~uint64_t{0};
      for (int32_t i = 0; i < 4; ++i) all &= TexelMask::bitsFromWords(shorter, count, 64 * k + i * span);
      words[k] = all;
    }
  }
  for (int32_t level = 0; level < kLevels; ++level) {
    uint64_t* summary = wordSummary_[level].data() + static_cast<size_t>(y) * summaryWords_;
    const uint64_t* words = spans_[level].row(y);
    for (int32_t k = moved.first; k <= moved.last; ++k) {
      const uint64_t bit = uint64_t{1} << (k & 63);
      summary[k >> 6] = words[k] != 0 ? summary[k >> 6] | bit : summary[k >> 6] & ~bit;
    }
  }
}

bool AtlasOccupancy::runsFitAtRow(const ChartMask& mask, int32_t y) const {
  for (const MaskRun& run : mask.runs) {
    if (longestFreeRun_[y + run.row] < run.length) return false;
  }
  return true;
}

void AtlasOccupancy::prepareSpanTests(const ChartMask& mask) const {
  blockColumns_.clear();
  const BlockRun& block = mask.blocks[1];
  // Columns every 16 texels along the block's run, its last one included: far enough apart to rule out
  // different holes, few enough to cost less than the runs they spare.
  for (int32_t offset = 0; block.length > 0 && offset < block.length + 15; offset += 16)
    blockColumns_.push_back(block.start + std::min(offset, block.length - 1));
  blockRow_ = block.row;
  spanTests_.clear();
  for (const MaskRun& run : mask.runs) {
    int32_t level = 0, span = 1;
    while (level < 3 && span * 4 <= run.length) ++level, span *= 4;
    // Spans from the run's start, the last one ending with the run (overlapping its predecessor if need be).
    for (int32_t offset = 0; offset < run.length; offset += span)
      spanTests_.push_back({level, run.row, run.start + std::min(offset, run.length - span)});
  }
}

bool AtlasOccupancy::wordsThatMayFit(int32_t y, int32_t lastX) const {
  // A mask at a column of word k needs, for each test, a set bit in word k + from / 64 or the next one of the
  // test's spans; the summaries say which words have any.
  const int32_t lastWord = lastX / 64;
  candidateWords_.assign(summaryWords_, 0);
  for (int32_t k = 0; k <= lastWord; ++k) candidateWords_[k >> 6] |= uint64_t{1} << (k & 63);
  // The longest runs' tests rule out the most; the rest are left to the exact test.
  const size_t testsUsed = std::min<size_t>(spanTests_.size(), 8);
  for (size_t i = 0; i < testsUsed; ++i) {
    const SpanTest& test = spanTests_[i];
    const uint64_t* summary = wordSummary_[test.level].data() + static_cast<size_t>(y + test.row) * summaryWords_;
    const int32_t word = test.from >> 6;
    uint64_t any = 0;
    for (int32_t j = 0; j < summaryWords_; ++j) {
      const uint64_t mayStart = TexelMask::bitsFromWords(summary, summaryWords_, 64 * j + word) |
                                TexelMask::bitsFromWords(summary, summaryWords_, 64 * j + word + 1);
      candidateWords_[j] &= mayStart;
      any |= candidateWords_[j];
    }
    if (any == 0) return false;
  }
  return true;
}

uint64_t AtlasOccupancy::blockColumnsFree(int32_t y, int32_t word) const {
  uint64_t candidates = ~uint64_t{0};
  const uint64_t* row = freeInSixteenRows_.row(y + blockRow_);
  for (const int32_t column : blockColumns_) {
    // Bit i: column 64 · word + i + column is free in all 16 rows (reads stay in the row and its spare word).
    const uint64_t* words = row + (column >> 6) + word;
    const int32_t bit = column & 63;
    candidates &= (words[0] >> bit) | ((words[1] << 1) << (63 - bit));
    if (candidates == 0) break;
  }
  return candidates;
}

std::optional<int32_t> AtlasOccupancy::leftmostFitInRow(int32_t y, int32_t lastX) const {
  const int32_t lastWord = lastX / 64;
  const size_t testCount = spanTests_.size();
  // Word by word from the left, so that the first word left with a candidate holds the leftmost fit. The tests
  // run in a cycle from the one that last emptied a word: neighbouring words and rows are mostly ruled out by
  // the same part of the mask, so a word is usually given up after one test. Reads stay inside the row and its
  // spare word: a column is at most width − mask width and a span ends inside the mask.
  if (!wordsThatMayFit(y, lastX)) return std::nullopt;
  for (int32_t k = 0; k <= lastWord; ++k) {
    if (!((candidateWords_[k >> 6] >> (k & 63)) & 1)) continue;
    uint64_t candidates = k < lastWord ? ~uint64_t{0} : ~uint64_t{0} >> (63 - (lastX & 63));
    candidates &= blockColumnsFree(y, k);
    if (candidates == 0) continue;
    for (size_t done = 0, i = lastEmptyingTest_; done < testCount; ++done, i = i + 1 == testCount ? 0 : i + 1) {
      const SpanTest& test = spanTests_[i];
      const uint64_t* words = spans_[test.level].row(y + test.row) + (test.from >> 6) + k;
      const int32_t bit = test.from & 63;
      candidates &= (words[0] >> bit) | ((words[1] << 1) << (63 - bit));
      if (candidates == 0) {
        lastEmptyingTest_ = i;
        break;
      }
    }
    if (candidates != 0) return 64 * k + __builtin_ctzll(candidates);
  }
  return std::nullopt;
}

std::optional<TexelPosition> AtlasOccupancy::firstFit(const ChartMask& mask, int32_t highestRow) const {
  const int32_t lastY = std::min(height() - mask.texels.height(), highestRow);
  const int32_t lastX = width() - mask.texels.width();
  if (lastX < 0) return std::nullopt;
  prepareSpanTests(mask);
  lastEmptyingTest_ = 0;
  for (int32_t y = lowestRowForBlocks(mask); y <= lastY; ++y) {
    if (!blocksFitAtRow(mask, y) || !runsFitAtRow(mask, y)) continue;
    if (const auto x = leftmostFitInRow(y, lastX)) return TexelPosition{*x, y};
  }
  return std::nullopt;
}

void AtlasOccupancy::claim(const ChartMask& mask, TexelPosition position) {
  const int32_t reach = static_cast<int32_t>(dilationReach_.size()) - 1;
  for (const MaskRun& run : mask.runs) {
    const int32_t x0 = position.x + run.start, x1 = x0 + run.length - 1, y = position.y + run.row;
    for (int32_t dy = -reach; dy <= reach; ++dy) {
      const int32_t dx = dilationReach_[std::abs(dy)];
      freeTexels().assignSpan(y + dy, x0 - dx, x1 + dx, false);
    }
  }
  const int32_t firstRow = std::max(0, position.y - reach);
  const int32_t lastRow = std::min(height() - 1, position.y + mask.texels.height() - 1 + reach);
  const int32_t reachX = dilationReach_[0];
  const WordRange changed{std::max(position.x - reachX, 0) >> 6,
                          std::min(position.x + mask.texels.width() - 1 + reachX, width() - 1) >> 6};
  for (int32_t y = firstRow; y <= lastRow; ++y) updateRow(y, changed);
  updateBlocks(firstRow, lastRow, changed);
}

}  // namespace straightest::atlas_detail
