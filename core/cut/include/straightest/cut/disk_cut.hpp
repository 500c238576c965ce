// disk_cut.hpp — any connected manifold mesh made a topological disk (one boundary loop, Euler
// characteristic 1), so that it can be parameterized; how it was done is reported, never silent.
//
// Of a mesh with several connected components only the largest (by face count; ties: the one with the
// lowest face index) is cut and parameterized; `component` and `components` say so. Then, with g the genus
// and k the number of boundary loops of that component (χ = 2 − 2g − k):
//  - k = 1, g = 0 (a disk): nothing to do (method Disk; the caller need not call cutToDisk at all).
//  - k ≥ 2, g = 0 (holes): every loop but the longest (by 3D length: the outer boundary, which the
//    measured boundary maps) is filled virtually — one new vertex at the loop's centroid, fanned to the
//    loop. Virtual vertices and faces take part in the solve (they keep a convex-combination map a disk
//    map, so Tutte/Floater still guarantee it is bijective) and never reach the output. Method Fill.
//  - k = 0, g = 0 (a sphere-like closed surface): cut along a seam, the shortest edge path between two
//    far-apart vertices (seamEnds: the vertex farthest by edge-graph distance from the component's
//    lowest-index vertex, then the one farthest from that — a double sweep that approximates the graph diameter, so the
//    seam runs the surface's length and the disk is not a thin sliver). Method Path. (A seam has at
//    least two edges — one edge cannot open a triangle mesh — so where the two are neighbours, as on a
//    tetrahedron, it goes on by one edge; seamEnds are its ends.)
//  - g ≥ 1: every boundary loop (the outer one too) is filled virtually, then the closed surface is cut
//    along a cut graph: tree–cotree (Eppstein 2003) — a shortest-path tree T of the primal edges from a
//    root, a spanning tree C of the dual over the edges not in T; the 2g edges in neither close 2g
//    loops through T; their union, pruned of dangling branches (repeatedly removing degree-1 vertices),
//    is the seam. Method CutGraph. C is a maximum spanning tree by the length of the loop each edge
//    would close, so the 2g loops left over are the short ones (a greedy system of loops: short, not
//    shortest). A filled loop's virtual vertex is a leaf of T and C takes the rest of its fan, so the
//    seam never runs through a filled hole: it is made of mesh edges.
// Cutting along the seam duplicates every seam vertex once per wedge of faces the seam separates
// around it; each seam edge then appears exactly twice on the disk's boundary loop.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/names.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

enum class CutMethod : uint8_t { Disk, Fill, Path, CutGraph };
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<CutMethod> kCutMethodNames[] = {{CutMethod::Disk, "disk"},
                                                          {CutMethod::Fill, "fill"},
                                                          {CutMethod::Path, "path"},
                                                          {CutMethod::CutGraph, "cut-graph"}};
const char* cutMethodName(CutMethod m);  // "disk", "fill", "path", "cut-graph"

struct DiskCut {
  TriMesh disk;                              // one boundary loop, χ = 1: what gets parameterized
  std::vector<int32_t> vertexOrigin;         // per disk vertex: the mesh vertex it copies; −1 for a virtual one
  std::vector<int32_t> faceOrigin;           // per disk face: the mesh face it is; −1 for a virtual (filling) face
  std::vector<std::array<int32_t, 2>> seam;  // mesh edges cut open, as mesh vertex pairs (each edge once)
  std::vector<int32_t> filledLoops;          // indices into mesh.boundaryLoops() filled virtually
  CutMethod method = CutMethod::Disk;
  int32_t genus = 0;                        // of the parameterized component
  std::array<int32_t, 2> seamEnds{-1, -1};  // method Path: the two far-apart mesh vertices the seam joins
  int32_t component = 0;                    // which one: components are numbered by their lowest face index
  int32_t components = 1;                   // how many the mesh has
  int64_t faces = 0;                        // mesh faces in the parameterized component
  double seamLength = 0;                    // 3D length of the seam
};

/// Cuts (and fills) the mesh's largest component into a disk, as the file comment says. Progress stage
/// "cut"; cancelling returns a Cancelled error. Errors: Topology when the component has no face.
Expected<DiskCut> cutToDisk(const TriMesh& mesh, const Progress& progress = {});

}  // namespace straightest
