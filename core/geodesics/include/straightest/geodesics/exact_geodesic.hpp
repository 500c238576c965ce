// exact_geodesic.hpp — exact polyhedral geodesic distance from a surface point to every vertex, and the
// shortest paths behind it, by window propagation (the improved Chen–Han algorithm, "ICH": Xin & Wang
// 2009, after Chen & Han 1990).
//
// A window is an interval of an edge whose points all see one source image (the source, or a
// pseudo-source vertex, unfolded into the plane of the edge's face) along straight lines across the
// faces behind it; the distance there is σ + |image − x| (σ: the pseudo-source's distance). Windows
// are propagated face by face in the order of their least distance (one priority queue, windows and
// pseudo-source events together). Shortest paths bend only at saddle vertices (total angle > 2π) and
// boundary vertices, so those become pseudo-sources once their distance is known, and emit windows of
// their own. Without the trimming of MMP, windows would multiply; ICH's filter drops a new window when
// one of the three corners of the face it came through already offers a shorter route to every point
// of it (d(corner) + |corner − x| < σ + |image − x|), or when the last window created on the same edge is
// shorter at every point of it (a cheap exact test: the difference of two such distances is monotone
// between two known points); the queue's peak stayed at 0.8–1.5 windows per vertex on the meshes measured,
// 300–250k vertices (see docs/ARCHITECTURE.md). The number of windows grows like n^1.5 on bumpy meshes:
// each saddle's shadow is a pencil of its own that splits at every vertex it meets.
// Unreferenced vertices and other components get +inf. Cost: O(windows) queue operations, each O(1) (a
// bucket queue over the keys just ahead of the front: keys only grow).
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/surface_point.hpp"

namespace straightest {

/// How a vertex's shortest distance was reached, for back-tracing: a window on `halfedge` whose rays
/// leave `origin` (a pseudo-source vertex, or −1 for the source point) seen at `image` in the
/// halfedge's frame (tail at (0, 0), head at (length, 0), face(halfedge) above the x axis), or, when
/// halfedge < 0, a straight segment from `origin` inside one face.
struct GeodesicParent {
  int32_t halfedge = -1;
  int32_t origin = -1;
  Vec2 image;
};

/// What the propagation cost.
struct ExactGeodesicStats {
  int64_t windows = 0;        // windows created (after the filter)
  int64_t filtered = 0;       // windows the filter dropped
  int64_t maxQueue = 0;       // the queue's peak (windows and events): the memory bound that matters
  int64_t pseudoSources = 0;  // pseudo-source emissions
};

/// Distances from one source to every vertex, with what is needed to back-trace shortest paths.
struct ExactGeodesics {
  SurfacePoint source;
  std::vector<double> distances;  // per vertex; +inf where unreachable
  std::vector<GeodesicParent> parents;
  ExactGeodesicStats stats;
};

/// Exact distances from a valid surface point (see validateSurfacePoint) to every vertex. Progress
/// stage "distances" (fraction of vertices reached); cancelling returns a Cancelled error. A queue
/// beyond 100 windows per face (never seen; a safeguard) is a TooLarge error.
Expected<ExactGeodesics> exactGeodesics(const TriMesh& mesh, const SurfacePoint& source, const Progress& progress = {});

/// The distances alone (no progress), for GeodesicDistances.
std::vector<double> exactGeodesicDistances(const TriMesh& mesh, const SurfacePoint& source);

/// The exact shortest path from the source to vertex `target` as a polyline (3D points, the source first,
/// then the crossings of edges and the pseudo-source vertices it bends at, the target last); its length is
/// distances[target] up to rounding. InvalidArgument for a vertex out of range or unreachable.
Expected<std::vector<Vec3>> exactShortestPath(const TriMesh& mesh, const ExactGeodesics& field, int32_t target);

}  // namespace straightest
