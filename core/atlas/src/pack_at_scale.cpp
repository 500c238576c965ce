// pack_at_scale.cpp — the greedy pass: every rotation's bottom-left first fit, the one whose top edge is lowest
// kept (then the leftmost), so the atlas fills from the bottom in the tightest orientation.
#include "pack_at_scale.hpp"

#include <limits>
#include <optional>

#include "atlas_occupancy.hpp"
#include "chart_raster.hpp"

namespace straightest::atlas_detail {
namespace {

struct Choice {
  ChartMask mask;
  TexelPosition position;
  int32_t top() const { return position.y + mask.texels.height(); }
};

bool betterThan(const Choice& a, const std::optional<Choice>& b) {
  if (!b) return true;
  if (a.top() != b->top()) return a.top() < b->top();
  return a.position.x < b->position.x;
}

/// The best rotation's first fit for one chart; nothing when no rotation fits.
std::optional<Choice> bestPlacement(const ChartShape& chart, const std::vector<double>& angles, double texelsPerUnit,
                                    AtlasOccupancy& occupancy) {
  std::optional<Choice> best;
  for (const double angle : angles) {
    auto raster = rasterizeChart(chart.triangles, texelsPerUnit, angle, occupancy.width(), occupancy.height());
    if (!raster) continue;
    ChartMask& mask = *raster;
    const int32_t h = mask.texels.height();
    // Only positions whose top can beat (or tie) the best so far are worth scanning.
    const int32_t highestRow = best ? best->top() - h : std::numeric_limits<int32_t>::max();
    const auto position = occupancy.firstFit(mask, highestRow);
    if (!position) continue;
    Choice choice{std::move(mask), *position};
    if (betterThan(choice, best)) best = std::move(choice);
  }
  return best;
}

}  // namespace

PackOutcome packAtScale(const std::vector<ChartShape>& charts, const ChartAngles& angles,
                        const std::vector<int32_t>& order, double texelsPerUnit, const AtlasFrame& frame,
                        const std::function<bool(double)>& keepGoing, std::vector<Placement>& placements) {
  AtlasOccupancy occupancy(frame.width, frame.height, frame.border, frame.padding);
  placements.assign(charts.size(), Placement{});
  for (size_t i = 0; i < order.size(); ++i) {
    if (!keepGoing(static_cast<double>(i) / order.size())) return PackOutcome::Cancelled;
    const int32_t chart = order[i];
    const auto choice = bestPlacement(charts[chart], angles[chart], texelsPerUnit, occupancy);
    if (!choice) return PackOutcome::DoesNotFit;
    occupancy.claim(choice->mask, choice->position);
    const Vec2 corner{static_cast<double>(choice->position.x), static_cast<double>(choice->position.y)};
    placements[chart] = Placement{choice->mask.angle, corner - choice->mask.origin};
  }
  return PackOutcome::Packed;
}

}  // namespace straightest::atlas_detail
