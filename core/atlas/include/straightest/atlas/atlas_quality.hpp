// atlas_quality.hpp — an independent measurement of a texture atlas given as uv per face corner: its charts
// (found from the uv alone), their topology, stretch, winding, overlaps, gaps and coverage.
//
// The same function measures any atlas (ours, xatlas's), so nothing here trusts the producer's chart ids
// or bookkeeping. Charts are the connected components of faces joined across mesh edges whose two
// endpoints have the same uv on both sides.
//
// Exactness. Every uv is snapped to the grid of 2^-24 (integer coordinates, |u| clamped to 2^15) and the
// orientation, crossing and point-in-triangle tests are exact integer predicates on the snapped points.
// Snapping loses nothing for a multiple of 2^-24: every float32 in [0.5, 1] is one (its spacing there is
// 2^-24, 2^-23 only at 1 itself), and so is any texel-aligned uv at a resolution dividing 2^24. A float32
// below 0.5 is finer than the grid and moves by at most 2^-25 (6e-5 texels at 1024), so for the npm output's
// float32 uv the tests are exact for the points as snapped, not for the float32 values below 0.5. Two
// corners are "the same uv" when they snap to the same point. Distances (gaps) are computed in double from
// the snapped points. Stretch uses the uv as given (not snapped), laid on texels (u × width, v × height, so
// that a non-square atlas does not count its aspect as stretch), and the exact winding only decides which
// faces are flipped or degenerate.
#pragma once
#include <cstdint>
#include <limits>
#include <vector>

#include "straightest/base/vec3.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

struct AtlasQuality {
  int32_t charts = 0;                      // connected components of faces joined across edges whose two endpoints have
                                           // the same uv on both sides (from the uv alone, not from any chart ids)
  int32_t nonDiskCharts = 0;               // charts that are not a topological disk (χ != 1, boundary loops != 1, or a
                                           // vertex where the boundary pinches), on the chart welded by (vertex, uv)
  double l2 = 0, linf = 0;                 // Sander stretch of the whole atlas, uv in texels scaled so uv area = 3D
                                           // area; inf when any face is flipped or degenerate or any uv is not finite
  std::vector<double> chartL2, chartLinf;  // per chart, each normalized by its own areas
  int64_t flipped = 0;         // faces whose uv winding differs from their chart's majority (3D-area-weighted)
  int64_t mirroredCharts = 0;  // charts whose majority winding is clockwise (against the TriMesh face)
  int64_t degenerate = 0;      // faces with no certain uv orientation (collinear when snapped and in double
                               // precision) whose 3D area is not zero
  int64_t overlaps = 0;        // chart pairs that overlap (boundary edges properly crossing, or a vertex, a
                               // boundary edge's midpoint or a face centroid of one strictly inside a
                               // triangle of the other) + charts whose boundary properly crosses itself
  std::vector<int32_t> overlappingFaces;  // the first face of each chart counted in overlaps, ascending
  double minGapTexels = std::numeric_limits<double>::infinity();  // smallest distance between two charts
                                                                  // in texels; 0 if any touch or overlap
  int64_t paddingViolations = 0;  // chart pairs closer than options.padding texels (overlapping pairs too), less
                                  // the snapping's rounding (√2 · 2^-24 of the atlas side)
  double utilization = 0;         // Σ |uv triangle area| in [0,1]² units (overlaps count twice)
  int64_t outside = 0;            // finite corners outside [0,1]²
  int64_t nonFinite = 0;          // NaN/inf uv corners (their faces join no chart edge and are not measured)
  int64_t seamEdges = 0;          // interior mesh edges whose two sides have different uv
  double seamLength = 0;          // their total 3D length
};

struct QualityOptions {
  int32_t width = 1024, height = 1024;  // texels, for minGapTexels and padding
  double padding = 0;                   // texels
};

/// Measures the atlas cornerUv (3 per face: cornerUv[3f + k] belongs to mesh.triangle(f)[k]).
/// Throws std::invalid_argument when cornerUv.size() != 3 × faces or width/height are not positive.
AtlasQuality measureAtlas(const TriMesh& mesh, const std::vector<Vec2>& cornerUv, const QualityOptions& options = {});

}  // namespace straightest
