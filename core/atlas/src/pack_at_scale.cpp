// pack_at_scale.cpp — the greedy pass: every rotation's bottom-left first fit, the one whose texels' centre
// lies lowest kept (then the leftmost), so the atlas fills from the bottom with each chart's bulk as low as
// it goes: a lowest top edge instead keeps a chart's short side up and leaves its overhangs over empty
// texels, which later charts rarely fill.
#include "pack_at_scale.hpp"

#include <cmath>
#include <limits>

#include "straightest/base/parallel_for.hpp"

namespace straightest::atlas_detail {
namespace {

struct Choice {
  const ChartMask* mask = nullptr;
  TexelPosition position;
  double centre() const { return position.y + mask->centroidRow; }
};

bool betterThan(const Choice& a, const std::optional<Choice>& b) {
  if (!b) return true;
  if (a.centre() != b->centre()) return a.centre() < b->centre();
  return a.position.x < b->position.x;
}

/// The best rotation's first fit for one chart; nothing when no rotation fits.
std::optional<Choice> bestPlacement(const std::vector<std::optional<ChartMask>>& masks, Rotations rotations,
                                    AtlasOccupancy& occupancy) {
  // The right angles are every (n / 4)-th of a chart's n evenly spread turns (ChartAngles).
  const size_t step = rotations == Rotations::RightAngles && masks.size() >= 4 ? masks.size() / 4 : 1;
  std::optional<Choice> best;
  for (size_t k = 0; k < masks.size(); k += step) {
    const auto& mask = masks[k];
    if (!mask) continue;
    // Only positions whose centre can beat (or tie) the best so far are worth scanning.
    const int32_t highestRow = best ? static_cast<int32_t>(std::floor(best->centre() - mask->centroidRow))
                                    : std::numeric_limits<int32_t>::max();
    const auto position = occupancy.firstFit(*mask, highestRow);
    if (!position) continue;
    const Choice choice{&*mask, *position};
    if (betterThan(choice, best)) best = choice;
  }
  return best;
}

}  // namespace

std::optional<ChartMasks> rasterizeAll(const std::vector<ChartShape>& charts, const ChartAngles& angles,
                                       double texelsPerUnit, const AtlasFrame& frame, const Progress& progress) {
  ChartMasks masks(charts.size());
  auto body = [&](size_t, size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      // The turns are evenly spread over the full turn: with a multiple of 4 of them, each turn a quarter
      // after an earlier one is that one's mask turned.
      const size_t quarter = angles[c].size() % 4 == 0 ? angles[c].size() / 4 : angles[c].size();
      for (size_t k = 0; k < angles[c].size(); ++k) {
        const auto& earlier = k >= quarter ? masks[c][k - quarter] : std::nullopt;
        masks[c].push_back(
            earlier ? quarterTurned(*earlier, angles[c][k], frame.width, frame.height)
                    : rasterizeChart(charts[c].triangles, texelsPerUnit, angles[c][k], frame.width, frame.height));
      }
    }
  };
  if (!detail::parallelFor(charts.size(), 1, body, progress, "pack")) return std::nullopt;
  return masks;
}

PackOutcome packMasks(const ChartMasks& masks, const std::vector<int32_t>& order, Rotations rotations,
                      PackingSpace& space, const std::function<bool(double)>& keepGoing,
                      std::vector<Placement>& placements) {
  AtlasOccupancy& occupancy = space.emptied();
  placements.assign(masks.size(), Placement{});
  for (size_t i = 0; i < order.size(); ++i) {
    if (!keepGoing(static_cast<double>(i) / order.size())) return PackOutcome::Cancelled;
    const int32_t chart = order[i];
    const auto choice = bestPlacement(masks[chart], rotations, occupancy);
    if (!choice) return PackOutcome::DoesNotFit;
    occupancy.claim(*choice->mask, choice->position);
    const Vec2 corner{static_cast<double>(choice->position.x), static_cast<double>(choice->position.y)};
    placements[chart] = Placement{choice->mask->angle, corner - choice->mask->origin};
  }
  return PackOutcome::Packed;
}

}  // namespace straightest::atlas_detail
