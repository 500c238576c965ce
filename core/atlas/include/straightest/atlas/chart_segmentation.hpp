// chart_segmentation.hpp — a mesh cut into charts, each flattened on its own (the first half of a texture atlas).
//
// Segmentation (stage "segment"): seeds by farthest-point sampling over the face-adjacency graph (edges
// weighted by centroid distance), as many per connected component as its total absolute Gaussian
// curvature asks for; charts grow from them through one priority queue whose cost adds the face's normal
// deviation from the chart's area-weighted normal, its distance from the seed and how much it lengthens
// the chart's boundary (D-Charts / xatlas in spirit). A face whose normal leaves the chart's cone is left
// for another chart; faces no chart takes get new seeds (the farthest face of each region left), until
// every face has a chart. So every chart is edge-connected and lies in one component.
//
// Flattening (stage "flatten"): each chart becomes its own TriMesh (vertices where the chart's faces meet
// only at a corner are split, so it is manifold) and is mapped by parameterize with the free boundary
// (never folds; a chart that is not a disk is cut by parameterize), planar charts by projection and lone
// faces directly, all isometric in scale (3D units) and counter-clockwise. A chart that is not bijective
// or whose L2 stretch exceeds maxStretch or that fills less than minHullFill of its convex hull is split in two (two
// far-apart seeds, regrown inside it) and both halves are flattened again; a one-face chart is always accepted. Then
// adjacent charts are merged, smallest first, wherever their union still flattens bijectively within maxStretch.
//
// Charts are flattened in parallel (threads.hpp); each chart's map depends only on its faces, so the
// result is the same for any thread count.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/base/vec3.hpp"
#include "straightest/mesh/trimesh.hpp"
#include "straightest/param/free_boundary.hpp"

namespace straightest {

struct ChartOptions {
  double maxStretch = 1.02;  // per-chart Sander L2 target after flattening (>= 1); charts above it are split
  // 0: no cap. Otherwise at most this many charts where the surface allows: splits for stretch or shape stop at
  // it, and a segmentation with more charts is merged down to it whatever the stretch (ChartSet::capped). A chart
  // with no flat map is split anyway, and merges only make disks, so a closed surface keeps two or more.
  int32_t maxCharts = 0;
  // The least fraction of its uv's convex hull a chart may fill (0: any shape). A chart below it (an L, a
  // piece of a ring, a body with its legs) is split like a stretched one: convex pieces pack with few gaps,
  // so the atlas's texels go further, for a little more seam. Splits for shape count toward maxCharts.
  double minHullFill = 0.75;
  // The most faces a chart grows to or merges into (0: no cap). Without it a large smooth mesh becomes a few
  // huge charts whose refinement solves dominate and run one at a time; with it a big developable region
  // becomes several charts, which costs a texture a little seam and keeps every solve small and parallel.
  int32_t maxChartFaces = 5000;
  // Per-chart refinement caps. Fewer iterations and a looser tolerance than one whole-mesh map: a chart is
  // nearly developable, so its refinement converges early, and a chart that needs more is split anyway.
  FreeBoundaryOptions free{50, 1e-4, 60000};
};

struct FlatChart {
  std::vector<int32_t> faces;  // mesh faces of this chart, ascending
  std::vector<Vec2> cornerUv;  // 3 per face in `faces` order (corner k of mesh.triangle(f)), in 3D units,
                               // every triangle counter-clockwise with positive area (no mirror)
  double l2 = 1, linf = 1;     // Sander stretch of this chart (texture_stretch semantics, scale-invariant)
};

struct ChartSet {
  std::vector<FlatChart> charts;     // ordered by their first face
  std::vector<int32_t> chartOfFace;  // per mesh face
  int32_t splits = 0, merges = 0;    // charts split in two, pairs of charts merged
  double l2 = 1, linf = 1;           // the whole atlas's Sander stretch, every chart at its 3D scale
  int32_t overStretch = 0;           // charts left above maxStretch (only when maxCharts applied)
  bool capped = false;               // maxCharts stopped a split or merged charts
};

/// Errors: InvalidArgument (maxStretch < 1 or not finite, minHullFill outside [0, 1], maxCharts < 0,
/// maxChartFaces < 0), Cancelled, TooLarge.
Expected<ChartSet> makeCharts(const TriMesh& mesh, const ChartOptions& options, const Progress& progress = {});

/// Splits each chart of `charts` (indices into set.charts; a lone face is kept) in two and flattens the parts as
/// makeCharts does, splitting further any part that is not acceptable; the set is in makeCharts's order again
/// and its stretch up to date. For charts found to overlap once placed (buildAtlas). Errors: Cancelled.
Expected<void> splitCharts(const TriMesh& mesh, ChartSet& set, const std::vector<int32_t>& charts,
                           const ChartOptions& options, const Progress& progress = {});

}  // namespace straightest
