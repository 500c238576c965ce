// chart_mesh.hpp — one chart as a TriMesh of its own: its faces in the chart's order, vertices re-indexed,
// and a mesh vertex where the chart's faces meet in several fans (touching only at that corner) split
// into one vertex per fan, so the chart mesh is manifold and its edges are exactly the chart's inner edges.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest::atlas {

/// `faces` ascending. Face i of the result is faces[i] with the same corner order (the chart is consistently
/// oriented, so TriMesh::build reorients nothing). Errors: those of TriMesh::build (Degenerate when every
/// face of the chart has zero area).
Expected<TriMesh> buildChartMesh(const TriMesh& mesh, const std::vector<int32_t>& faces);

/// The index in `faces` (ascending) of face f, or -1.
int32_t localFace(const std::vector<int32_t>& faces, int32_t f);

}  // namespace straightest::atlas
