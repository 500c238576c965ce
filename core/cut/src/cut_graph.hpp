// cut_graph.hpp — where a closed surface is cut so that it opens into a disk: a seam of mesh edges.
//
// Two seams, both on a closed, connected TriMesh (every vertex interior), both measured by 3D edge
// lengths on the edge graph:
//  - pathSeam (genus 0): the shortest edge path between two far-apart vertices found by a double sweep
//    of Dijkstra (the vertex farthest from vertex 0, then the one farthest from that).
//  - treeCotreeSeam (genus g ≥ 1): a shortest-path tree T from vertex 0, a spanning tree C of the dual
//    over the edges not in T, the 2g edges in neither, each closing a loop through T; their union,
//    pruned of dangling branches. C is a maximum spanning tree by the length of the loop each edge would
//    close, so the loops left over are the short ones (a greedy system of loops).
// Vertices from `firstVirtual` on are virtual (the centres of filled holes): the seam never runs through
// one — T reaches each through one edge and never leaves it, and C takes every other edge of its fan.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest::detail {

struct Seam {
  std::vector<std::array<int32_t, 2>> edges;  // vertex pairs of the surface, each edge once
  std::array<int32_t, 2> ends{-1, -1};        // pathSeam: the path's two ends
};

/// The genus-0 seam: a simple path of at least two edges (on a tetrahedron, where the far-apart
/// vertices are neighbours, one more edge is added). Progress is reported in `stage`'s 0..1.
Expected<Seam> pathSeam(const TriMesh& closed, const Progress& progress, const char* stage);

/// The cut graph of a closed surface of genus ≥ 1 (see the file comment); its Euler characteristic is
/// 1 − 2g.
Expected<Seam> treeCotreeSeam(const TriMesh& closed, int32_t firstVirtual, const Progress& progress, const char* stage);

}  // namespace straightest::detail
