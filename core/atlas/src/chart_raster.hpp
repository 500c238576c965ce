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

struct ChartMask {
  TexelMask texels;
  double angle = 0;
  Vec2 origin{};                         // the texel-space point (rotated and scaled uv) at the mask's corner (0, 0)
  std::vector<MaskRun> runs;             // longest first: the runs most likely to find no room are tested first
  std::vector<int32_t> longestRunOfRow;  // per mask row
};

/// Every texel whose closed square the closed chart (its triangles, degenerate ones included) touches, after
/// the rotation `angle` and the scale `texelsPerUnit`. A margin of a millionth of a texel on every side absorbs
/// the rounding between this frame and the placement's (offset added after the rotation), so the chart's
/// continuous geometry, placed, lies inside the union of its texels' squares. Nothing when the mask would be
/// wider than maxWidth or taller than maxHeight (it could not fit, and a huge scale must not allocate).
std::optional<ChartMask> rasterizeChart(const std::vector<Vec2>& triangles, double texelsPerUnit, double angle,
                                        int32_t maxWidth, int32_t maxHeight);

}  // namespace straightest::atlas_detail
