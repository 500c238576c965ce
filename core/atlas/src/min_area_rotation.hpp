// min_area_rotation.hpp — the rotation that turns a chart's minimum-area bounding rectangle axis-aligned.
#pragma once
#include <vector>

#include "straightest/base/vec3.hpp"

namespace straightest::atlas_detail {

/// The convex hull of `points`, counter-clockwise, without collinear points (Andrew's monotone chain);
/// one or two points when they all coincide or lie on a line.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

/// The angle θ such that R(θ) maps the minimum-area bounding rectangle of `points` to an axis-aligned one
/// (one of the hull's edges becomes horizontal: the rotating-calipers theorem says the best rectangle has a
/// side on a hull edge). 0 for a point; a segment becomes horizontal.
double minAreaRectangleAngle(const std::vector<Vec2>& points);

}  // namespace straightest::atlas_detail
