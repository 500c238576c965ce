// chart_packing.hpp — packs flattened charts into one texture atlas: scaled to one texel density, rotated
// (never mirrored), placed on a texel occupancy bitmap so that no two charts come closer than `padding`.
//
// The guarantee is geometric, not per texel centre: every chart is rasterized conservatively (every texel its
// closed triangles touch, a point or a segment included), and two charts' texel sets are kept so far apart
// that the texel squares, hence the continuous triangles inside them, are at least `padding` texels apart
// (Euclidean). Every chart also keeps ceil(padding / 2) texels from the atlas border, so that copies of the
// atlas tiled side by side (repeat wrapping) keep the padding too. With padding 0 charts may touch, never overlap.
//
// Placement: charts in decreasing order of their minimum-rectangle area (then longest side, then area: the
// next order is tried when one does not fit), each at the rotation and position whose top edge is lowest,
// then leftmost, among every position where its texels are free. Rotations: the right angles of the chart's
// minimum-area rectangle; a chart whose longest side spans a quarter of the atlas or more (at the scale where
// the chart area would fill it) is also tried at 16 evenly spread turns, so that a long chart may lie along
// the diagonal; each scale is packed with all of them and then with the right angles alone.
//
// Scale: texelsPerUnit = 0 searches (bisection) the largest scale at which the greedy packing fits, within
// half a texel of the largest chart's extent or 0.5 %, whichever is finer. A given texelsPerUnit that does
// not fit is an error (TooLarge), never a silently smaller scale.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/base/vec3.hpp"

namespace straightest {

/// The largest atlas side accepted: it bounds the occupancy bitmaps the packer holds.
inline constexpr int32_t kMaxAtlasSide = 16384;

struct PackOptions {
  // Square atlas side in texels when width and height are 0. An atlas wider than 4096 texels is packed on a grid
  // k = ceil(side / 4096) times coarser and placed k times larger (so its gaps are multiples of k texels).
  int32_t resolution = 1024;
  int32_t width = 0, height = 0;  // both 0 (use resolution) or both positive
  double padding = 2;             // texels between any two charts; ceil(padding / 2) from the atlas border
  double texelsPerUnit = 0;       // 0: the largest scale at which everything fits
  bool rotate = true;  // turn charts: 16 turns from the minimum-area rectangle's angle (its right angles among them)
};

/// One chart: 3 uv points per triangle, in 3D units (the flattening's scale), counter-clockwise.
struct ChartShape {
  std::vector<Vec2> triangles;
};

/// atlas uv (texels) = texelsPerUnit * R(angle) * uv + offset: a rotation and a translation, never a mirror.
struct Placement {
  double angle = 0;
  Vec2 offset{};
};

struct Packing {
  int32_t width = 0, height = 0;
  double texelsPerUnit = 0;
  std::vector<Placement> placements;  // one per chart, in the input's order
  double utilization = 0;             // total uv triangle area * texelsPerUnit² / (width * height)
};

/// Packs `charts` (progress stage "pack"). Errors: InvalidArgument for bad options (a non-positive or
/// oversized side, negative or non-finite padding or texelsPerUnit) and for a chart that is empty, not made of
/// whole triangles or not finite; TooLarge when a given texelsPerUnit does not fit, or when the charts cannot
/// fit at any scale (more charts than the atlas has padded texels for); Cancelled when progress says stop.
/// Zero-area charts and triangles are packed like any other (a point still takes its padded texels).
Expected<Packing> packCharts(const std::vector<ChartShape>& charts, const PackOptions& options,
                             const Progress& progress = {});

/// The atlas texel coordinates of `uv` on chart `chart`: texelsPerUnit * R(angle) * uv + offset.
Vec2 placeInTexels(const Packing& packing, int32_t chart, Vec2 uv);

/// The same point in [0,1]² (texels divided by width and height).
Vec2 placeInAtlas(const Packing& packing, int32_t chart, Vec2 uv);

}  // namespace straightest
