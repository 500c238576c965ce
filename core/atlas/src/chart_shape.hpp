// chart_shape.hpp — how well a flat chart packs: how much of its convex hull it fills.
#pragma once
#include <vector>

#include "straightest/base/vec3.hpp"

namespace straightest::atlas {

/// uv area / convex hull area of a chart's per-corner uv (every triangle counter-clockwise): 1 for a convex
/// chart, small for an L, a piece of a ring or a comb; 1 when the hull has no area.
double hullFill(const std::vector<Vec2>& cornerUv);

}  // namespace straightest::atlas
