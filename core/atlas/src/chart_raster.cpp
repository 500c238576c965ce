// chart_raster.cpp — conservative rasterization: per triangle and texel row, the x-extent of the triangle
// clipped to the row's closed strip, so that every touched texel is set however thin or degenerate the triangle.
#include "chart_raster.hpp"

#include <algorithm>
#include <limits>

namespace straightest::atlas_detail {
namespace {

constexpr double kMargin = 1e-6;  // texels; see rasterizeChart

struct Extent {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void include(double x) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  bool empty() const { return lo > hi; }
};

/// The x-extent of the closed triangle abc clipped to the strip y0 ≤ y ≤ y1: the clipped polygon's vertices
/// are the triangle's vertices inside the strip and its edges' crossings of the strip's two lines.
Extent extentInStrip(const Vec2 (&corner)[3], double y0, double y1) {
  Extent extent;
  for (int i = 0; i < 3; ++i) {
    const Vec2 a = corner[i], b = corner[(i + 1) % 3];
    if (a.y >= y0 && a.y <= y1) extent.include(a.x);
    for (const double y : {y0, y1}) {
      if (y > std::min(a.y, b.y) && y < std::max(a.y, b.y)) extent.include(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
  }
  return extent;
}

void rasterizeTriangle(const Vec2 (&corner)[3], TexelMask& mask) {
  const double yMin = std::min({corner[0].y, corner[1].y, corner[2].y});
  const double yMax = std::max({corner[0].y, corner[1].y, corner[2].y});
  const int32_t firstRow = std::max(0, static_cast<int32_t>(std::floor(yMin - kMargin)));
  const int32_t lastRow = std::min(mask.height() - 1, static_cast<int32_t>(std::floor(yMax + kMargin)));
  if (firstRow == lastRow) {
    // Most triangles of a dense chart lie in one row's strip: the clipped extent is the whole triangle's.
    const double xMin = std::min({corner[0].x, corner[1].x, corner[2].x});
    const double xMax = std::max({corner[0].x, corner[1].x, corner[2].x});
    mask.assignSpan(firstRow, static_cast<int32_t>(std::floor(xMin - kMargin)),
                    static_cast<int32_t>(std::floor(xMax + kMargin)), true);
    return;
  }
  for (int32_t row = firstRow; row <= lastRow; ++row) {
    const Extent extent = extentInStrip(corner, row - kMargin, row + 1 + kMargin);
    if (extent.empty()) continue;
    mask.assignSpan(row, static_cast<int32_t>(std::floor(extent.lo - kMargin)),
                    static_cast<int32_t>(std::floor(extent.hi + kMargin)), true);
  }
}

int32_t bitCount(const uint64_t* words, int32_t count) {
  int32_t bits = 0;
  for (int32_t k = 0; k < count; ++k) bits += __builtin_popcountll(words[k]);
  return bits;
}

/// Per block height, the block of rows with the longest common run (ChartMask::blocks). Blocks of 16 rows are
/// four blocks of 4, as in the occupancy's.
void findBlocks(ChartMask& mask) {
  static_assert(kBlockRows[0] == 4 && kBlockRows[1] == 16, "blocks of 16 rows are four blocks of 4");
  const TexelMask& texels = mask.texels;
  const int32_t words = texels.wordsPerRow();
  TexelMask four(texels.width(), std::max(texels.height() - 3, 0));
  for (int32_t row = 0; row < four.height(); ++row) {
    uint64_t* common = four.row(row);
    std::copy(texels.row(row), texels.row(row) + words, common);
    for (int32_t i = 1; i < 4; ++i)
      for (int32_t k = 0; k < words; ++k) common[k] &= texels.row(row + i)[k];
    // No run is longer than the row's count of set bits: a row that cannot beat the longest so far is not scanned.
    if (bitCount(common, words) <= mask.blocks[0].length) continue;
    int32_t start = 0;
    const int32_t length = longestRunOfBits(common, texels.width(), &start);
    if (length > mask.blocks[0].length) mask.blocks[0] = {row, start, length};
  }
  std::vector<uint64_t> common(words);
  for (int32_t row = 0; row + 16 <= texels.height(); ++row) {
    for (int32_t k = 0; k < words; ++k)
      common[k] = four.row(row)[k] & four.row(row + 4)[k] & four.row(row + 8)[k] & four.row(row + 12)[k];
    if (bitCount(common.data(), words) <= mask.blocks[1].length) continue;
    int32_t start = 0;
    const int32_t length = longestRunOfBits(common.data(), texels.width(), &start);
    if (length > mask.blocks[1].length) mask.blocks[1] = {row, start, length};
  }
}

/// Transposes the 64 × 64 bit matrix `rows` (bit j of row i ↔ bit i of row j) by swapping its off-diagonal
/// blocks of 32 × 32 bits, then within each quarter those of 16 × 16, and so on down to single bits.
void transpose64(uint64_t (&rows)[64]) {
  uint64_t lowHalves = 0x00000000FFFFFFFFull;  // per block of 2j columns, its j low ones
  for (int32_t j = 32; j != 0; j >>= 1, lowHalves ^= lowHalves << j) {
    for (int32_t k = 0; k < 64; k = ((k | j) + 1) & ~j) {
      const uint64_t swapped = ((rows[k] >> j) ^ rows[k | j]) & lowHalves;
      rows[k] ^= swapped << j;
      rows[k | j] ^= swapped;
    }
  }
}

/// The runs by decreasing length, runs of one length in their order (a counting sort: lengths are at most the
/// mask's width).
void sortLongestFirst(std::vector<MaskRun>& runs, int32_t width) {
  std::vector<int32_t> firstOfLength(width + 2, 0);
  for (const MaskRun& run : runs) ++firstOfLength[width - run.length + 1];
  for (int32_t i = 1; i <= width + 1; ++i) firstOfLength[i] += firstOfLength[i - 1];
  std::vector<MaskRun> sorted(runs.size());
  for (const MaskRun& run : runs) sorted[firstOfLength[width - run.length]++] = run;
  runs.swap(sorted);
}

/// The runs of set texels of every row, longest first.
void collectRuns(ChartMask& mask) {
  const TexelMask& texels = mask.texels;
  double rowSum = 0, count = 0;
  for (int32_t row = 0; row < texels.height(); ++row) {
    for (int32_t start = texels.nextWithBit(row, 0, true); start < texels.width();) {
      const int32_t end = texels.nextWithBit(row, start, false);
      mask.runs.push_back({row, start, end - start});
      rowSum += (row + 0.5) * (end - start), count += end - start;
      start = texels.nextWithBit(row, end, true);
    }
  }
  mask.centroidRow = count > 0 ? rowSum / count : 0;
  sortLongestFirst(mask.runs, texels.width());
}

}  // namespace

std::optional<ChartMask> rasterizeChart(const std::vector<Vec2>& triangles, double texelsPerUnit, double angle,
                                        int32_t maxWidth, int32_t maxHeight) {
  std::vector<Vec2> placed(triangles.size());
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}, hi = -lo;
  for (size_t i = 0; i < triangles.size(); ++i) {
    placed[i] = rotatedAndScaled(triangles[i], texelsPerUnit, angle);
    lo = {std::min(lo.x, placed[i].x), std::min(lo.y, placed[i].y)};
    hi = {std::max(hi.x, placed[i].x), std::max(hi.y, placed[i].y)};
  }
  ChartMask mask;
  mask.angle = angle;
  // Two margins below the lowest point keep the margin-widened lowest texel at index 0.
  mask.origin = lo - Vec2{2 * kMargin, 2 * kMargin};
  const Vec2 extent = hi - mask.origin;
  if (!(extent.x + kMargin < maxWidth && extent.y + kMargin < maxHeight)) return std::nullopt;
  mask.texels = TexelMask(static_cast<int32_t>(std::floor(extent.x + kMargin)) + 1,
                          static_cast<int32_t>(std::floor(extent.y + kMargin)) + 1);
  for (size_t t = 0; t + 2 < placed.size(); t += 3) {
    const Vec2 corner[3] = {placed[t] - mask.origin, placed[t + 1] - mask.origin, placed[t + 2] - mask.origin};
    rasterizeTriangle(corner, mask.texels);
  }
  collectRuns(mask);
  findBlocks(mask);
  return mask;
}

std::optional<ChartMask> quarterTurned(const ChartMask& mask, double angle, int32_t maxWidth, int32_t maxHeight) {
  const TexelMask& from = mask.texels;
  if (!(from.height() < maxWidth && from.width() < maxHeight)) return std::nullopt;
  ChartMask turned;
  turned.angle = angle;
  // Texel (i, j) covers [o.x + i, +1] × [o.y + j, +1]; (x, y) → (−y, x) takes it to texel (H − 1 − j, i) of the
  // grid whose corner is (−o.y − H, o.x).
  turned.origin = {-mask.origin.y - from.height(), mask.origin.x};
  turned.texels = TexelMask(from.height(), from.width());
  // So turned row i, bit x is texel (i, H − 1 − x): blocks of 64 × 64 texels of the rows read top down, transposed.
  const int32_t height = from.height();
  for (int32_t block = 0; 64 * block < height; ++block) {
    for (int32_t word = 0; 64 * word < from.width(); ++word) {
      uint64_t bits[64], any = 0, all = ~uint64_t{0};
      for (int32_t i = 0; i < 64; ++i) {
        const int32_t row = height - 1 - (64 * block + i);
        bits[i] = row >= 0 ? from.row(row)[word] : 0;
        any |= bits[i], all &= bits[i];
      }
      // Most blocks of a chart lie wholly outside or inside it: empty or full, they are their own transpose.
      if (any == 0) continue;
      if (all != ~uint64_t{0}) transpose64(bits);
      for (int32_t i = 0; i < 64 && 64 * word + i < from.width(); ++i)
        turned.texels.row(64 * word + i)[block] = bits[i];
    }
  }
  collectRuns(turned);
  findBlocks(turned);
  return turned;
}

}  // namespace straightest::atlas_detail
