// texture_stretch.hpp — distortion of a parameterization (Sander, Snyder, Gortler, Hoppe 2001).
// Per triangle, with S_s, S_t the partial derivatives of the 3D position with respect to (s, t):
// a = S_s·S_s, b = S_s·S_t, c = S_t·S_t; L2 = sqrt((a + c)/2); L∞ = sqrt(((a + c) + sqrt((a − c)² + 4b²))/2).
// Mesh L2 = sqrt(Σ L2² A3 / Σ A3), L∞ = max L∞, both times sqrt(Σ A2 / Σ A3) so an isometry (and any
// uniform scale of one) scores 1. A triangle with 2D area ≤ kDegenerateUV × mean |2D area| is
// degenerate, a negative one flipped; either makes the map non-bijective and the stretch infinite, and
// so does a boundary that crosses itself in the plane (boundary_overlaps.hpp: the texture would be
// sampled twice there even with every triangle positive).
// Angle distortion: Γ/γ (ratio of singular values), area-weighted mean and max. Area distortion: per
// face the ratio σ of normalized 2D to 3D area, reported as the area-weighted mean and max of
// max(σ, 1/σ). Zero-area 3D faces are skipped.
#pragma once
#include <vector>

#include "straightest/param/boundary_map.hpp"

namespace straightest {

inline constexpr double kDegenerateUV = 1e-12;

struct StretchMetrics {
  double l2 = 0, linf = 0;  // +inf when not bijective
  int64_t flipped = 0, degenerate = 0;
  int64_t overlaps = 0;  // crossing pairs of boundary edges (boundaryOverlaps)
  bool bijective = true;
  double angleDistortionMean = 1, angleDistortionMax = 1;
  double areaDistortionMean = 1, areaDistortionMax = 1;
  std::vector<float> faceStretch;  // per-face L2 stretch (normalized like the mesh L2); inf if flipped/degenerate
};

StretchMetrics textureStretch(const TriMesh& mesh, const std::vector<Vec2>& uv);

}  // namespace straightest
