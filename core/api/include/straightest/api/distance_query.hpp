// distance_query.hpp — distances from a source to vertex targets by a chosen method, with the exact
// shortest paths when asked: the one call behind the CLI's `distances` and npm's `exactShortestPaths`.
#pragma once
#include <vector>

#include "straightest/base/progress.hpp"
#include "straightest/base/timings.hpp"
#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"

namespace straightest {

struct DistanceQuery {
  DistanceTable table;                   // source, method, targets, one distance per target (+inf: unreachable)
  ExactGeodesicStats exact;              // the window propagation's cost (method Exact)
  std::vector<std::vector<Vec3>> paths;  // per target, its exact shortest path (when asked; empty: unreachable)
};

/// `targets` are vertices (empty: every vertex). keepPaths needs method Exact (else InvalidArgument).
/// Records "distances" and, with keepPaths, "paths" in `timings`. Errors: the propagation's, Cancelled.
Expected<DistanceQuery> queryDistances(const TriMesh& mesh, const SurfacePoint& source, DistanceMethod method,
                                       std::vector<int32_t> targets, bool keepPaths, const Progress& progress = {},
                                       Timings* timings = nullptr);

}  // namespace straightest
