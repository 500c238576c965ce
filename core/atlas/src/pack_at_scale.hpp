// pack_at_scale.hpp — one greedy packing at a fixed texel density: every chart's rotations rasterized once
// (in parallel), then charts placed in a given order, each at the rotation and first-fit position that keep
// its top edge lowest.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "atlas_occupancy.hpp"
#include "chart_raster.hpp"
#include "straightest/atlas/chart_packing.hpp"

namespace straightest::atlas_detail {

struct AtlasFrame {
  int32_t width = 0, height = 0, border = 0;
  double padding = 0;
};

/// The atlas packings place charts in: each packing starts from a copy of the empty atlas assigned into the
/// storage of the last one, as building the empty atlas's spans and blocks, or allocating fresh bitmaps, for
/// every packing costs more than the copy.
class PackingSpace {
 public:
  explicit PackingSpace(const AtlasFrame& frame)
      : empty_(frame.width, frame.height, frame.border, frame.padding), work_(empty_) {}
  AtlasOccupancy& emptied() {
    work_ = empty_;
    return work_;
  }

 private:
  AtlasOccupancy empty_, work_;
};

/// Per chart, the rotations worth trying: turns evenly spread over the full turn from the minimum-area
/// rectangle's angle, 4 of them (its right angles) or a multiple of 4 (the right angles every n / 4), or 0 alone.
using ChartAngles = std::vector<std::vector<double>>;

/// Which of a chart's rotations a packing tries: all, or the right angles of its minimum-area rectangle.
enum class Rotations { All, RightAngles };

/// Per chart, one mask per rotation (nothing where the rotated chart is larger than the atlas).
using ChartMasks = std::vector<std::vector<std::optional<ChartMask>>>;

enum class PackOutcome { Packed, DoesNotFit, Cancelled };

/// Every chart rasterized at every one of its rotations at `texelsPerUnit`, charts on the core's threads
/// (each mask depends only on its chart, so any thread count gives the same masks). `progress` is asked as
/// the charts go; false cancels (nothing then).
std::optional<ChartMasks> rasterizeAll(const std::vector<ChartShape>& charts, const ChartAngles& angles,
                                       double texelsPerUnit, const AtlasFrame& frame, const Progress& progress);

/// Places every chart, in `order`, from its masks (those of `rotations`) into the emptied `space`; `placements`
/// (one per chart, input order) is complete only when the outcome is Packed. `keepGoing(fraction)` is asked as
/// the charts go; false cancels.
PackOutcome packMasks(const ChartMasks& masks, const std::vector<int32_t>& order, Rotations rotations,
                      PackingSpace& space, const std::function<bool(double)>& keepGoing,
                      std::vector<Placement>& placements);

}  // namespace straightest::atlas_detail
