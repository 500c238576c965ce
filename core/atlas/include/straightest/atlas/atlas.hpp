// atlas.hpp — a texture atlas of any manifold mesh: charts (chart_segmentation.hpp), each flattened with
// the never-folding free boundary, packed into one texture (chart_packing.hpp), then measured by the
// independent check (atlas_quality.hpp), so every guarantee the result states is a measurement of the
// uv it returns, not the packer's bookkeeping.
//
// Several meshes share one atlas (lightmaps) by being combined first (combineMeshes): each mesh is a
// component of the union, charts never span components, and the result's faces are the meshes' faces in
// order.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/atlas/atlas_quality.hpp"
#include "straightest/atlas/chart_packing.hpp"
#include "straightest/atlas/chart_segmentation.hpp"
#include "straightest/base/timings.hpp"

namespace straightest {

struct AtlasOptions {
  ChartOptions charts;         // maxStretch, maxCharts, the per-chart refinement's caps
  PackOptions pack;            // resolution (or width × height), padding in texels, texelsPerUnit, rotation
  Timings* timings = nullptr;  // receives "segment" + "flatten" (as "charts"), "pack", "measure", "total"
};

struct Atlas {
  std::vector<Vec2> cornerUv;        // 3 per mesh face, in [0, 1]² (u right, v up, scaled by width/height)
  std::vector<int32_t> chartOfFace;  // per mesh face
  int32_t charts = 0;
  int32_t width = 0, height = 0;             // texels
  double texelsPerUnit = 0;                  // texels per unit of 3D length (every chart at one density)
  double utilization = 0;                    // uv area / atlas area
  std::vector<std::array<int32_t, 2>> seam;  // mesh edges whose two sides have different uv (vertex pairs)
  double seamLength = 0;                     // their 3D length
  int32_t splits = 0, merges = 0;            // segmentation's bookkeeping
  bool capped = false;                       // maxCharts stopped a split or merged charts (some may exceed maxStretch)
  AtlasQuality quality;                      // the independent measurement of cornerUv (l2, linf, flipped,
                                             // mirroredCharts, overlaps, minGapTexels, paddingViolations, …)
};

/// Progress stages "segment", "flatten", "pack", "measure", each from 0 to 1 (pack once more after a re-split of
/// charts that overlapped once placed); cancelling returns a Cancelled error. Errors:
/// makeCharts' and packCharts' (InvalidArgument for bad options), Cancelled.
Expected<Atlas> buildAtlas(const TriMesh& mesh, const AtlasOptions& options = {}, const Progress& progress = {});

/// The meshes as one mesh, each a component (faces and vertices in order, meshes[i]'s offset by those
/// of the meshes before it): one atlas for several meshes is buildAtlas of their union.
Expected<TriMesh> combineMeshes(const std::vector<const TriMesh*>& meshes);

}  // namespace straightest
