// distance_query.cpp — distances to vertex targets and their exact paths (distance_query.hpp).
#include "straightest/api/distance_query.hpp"

#include <numeric>

namespace straightest {
namespace {

void record(Timings* timings, const char* stage, double ms) {
  if (timings) timings->add(stage, ms);
}

}  // namespace

Expected<DistanceQuery> queryDistances(const TriMesh& mesh, const SurfacePoint& source, DistanceMethod method,
                                       std::vector<int32_t> targets, bool keepPaths, const Progress& progress,
                                       Timings* timings) {
  if (keepPaths && method != DistanceMethod::Exact)
    return Error{ErrorCode::InvalidArgument, "shortest paths need the exact method"};
  if (targets.empty()) {
    targets.resize(mesh.numVertices());
    std::iota(targets.begin(), targets.end(), 0);
  }
  DistanceQuery query{DistanceTable{source, method, std::move(targets), {}}, {}, {}};
  Stopwatch clock;
  std::vector<double> all;
  if (method == DistanceMethod::Exact) {
    auto field = exactGeodesics(mesh, source, progress);
    if (!field) return field.error();
    record(timings, "distances", clock.lap());
    query.exact = field.value().stats;
    for (int32_t t : keepPaths ? query.table.targets : std::vector<int32_t>{}) {
      auto path = exactShortestPath(mesh, field.value(), t);
      query.paths.push_back(path ? std::move(path).value() : std::vector<Vec3>{});
    }
    if (keepPaths) record(timings, "paths", clock.lap());
    all = std::move(field).value().distances;
  } else {
    all = GeodesicDistances(mesh).from(source, method);
    record(timings, "distances", clock.lap());
  }
  for (int32_t t : query.table.targets) query.table.distances.push_back(all[t]);
  return query;
}

}  // namespace straightest
