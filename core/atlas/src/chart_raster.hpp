// chart_raster.hpp — a chart rotated and scaled into texels, rasterized conservatively into a texel mask.
#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "straightest/base/vec3.hpp"
#include "texel_mask.hpp"

namespace straightest::atlas_detail {

/// texelsPerUnit * R(angle) * uv: the one formula both the rasterizer and placeInTexels evaluate, so that
/// the mask and the reported placement describe the same points.
inline Vec2 rotatedAndScaled(Vec2 uv, double texelsPerUnit, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2{c * uv.x - s * uv.y, s * uv.x + c * uv.y} * texelsPerUnit;
}

/// A run of set texels in one row of a mask.
struct MaskRun {
  int32_t row = 0, start = 0, length = 0;
};

/// The rows of a block of a mask and the longest run of columns set in all of them.
struct BlockRun {
  int32_t row = 0, start = 0, length = 0;
};

/// Heights of the blocks of rows ChartMask::blocks and the occupancy's free blocks describe.
inline constexpr int32_t kBlockRows[2] = {4, 16};

struct ChartMask {
  TexelMask texels;
  double angle = 0;
  Vec2 origin{};              // the texel-space point (rotated and scaled uv) at the mask's corner (0, 0)
  std::vector<MaskRun> runs;  // longest first: the runs most likely to find no room are tested first
  double centroidRow = 0;     // the mean row of the set texels' centres, from row 0's bottom
  // Per height in kBlockRows, the block of that many consecutive rows with the longest run of columns set in
  // all of them (length 0 when the mask is lower): a place whose rows have no such common free run is no fit,
  // which rules out the thin holes between placed charts in one test.
  BlockRun blocks[2];
};

/// Every texel whose closed square the closed chart (its triangles, degenerate ones included) touches, after
/// the rotation `angle` and the scale `texelsPerUnit`. A margin of a millionth of a texel on every side absorbs
/// the rounding between this frame and the placement's (offset added after the rotation), so the chart's
/// continuous geometry, placed, lies inside the union of its texels' squares. Nothing when the mask would be
/// wider than maxWidth or taller than maxHeight (it could not fit, and a huge scale must not allocate).
std::optional<ChartMask> rasterizeChart(const std::vector<Vec2>& triangles, double texelsPerUnit, double angle,
                                        int32_t maxWidth, int32_t maxHeight);

/// `mask` turned a quarter counter-clockwise, as the mask of the same chart at `angle` (the mask's angle + π/2):
/// the texel grid turns onto itself, so the turned texels are exactly the squares the turned chart touches
/// (only the origin moves), and no triangle is rasterized again. Nothing when it would be wider than maxWidth
/// or taller than maxHeight.
std::optional<ChartMask> quarterTurned(const ChartMask& mask, double angle, int32_t maxWidth, int32_t maxHeight);

}  // namespace straightest::atlas_detail
