#include "straightest/compare_parameterizations.hpp"

#include "straightest/geodesic_distance.hpp"

namespace straightest {

Expected<Comparison> compareParameterizations(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                              const std::vector<BoundaryKind>& boundaries,
                                              const std::vector<WeightKind>& weights, LinearSolver solver,
                                              const Progress& progress) {
  auto disk = requireDisk(mesh);
  if (!disk) return disk.error();
  // One source for every cell; one the measured boundary cannot use fails those cells only.
  std::optional<SurfacePoint> resolved = source;
  if (!source) {
    auto s = resolveSource(mesh, std::nullopt);
    if (s) resolved = s.value();
  }
  Comparison comparison;
  const double cells = static_cast<double>(boundaries.size() * weights.size());
  for (BoundaryKind boundary : boundaries)
    for (WeightKind weight : weights) {
      const double done = static_cast<double>(comparison.rows.size()) / cells;
      if (!report(progress, "compare", done)) return cancelledError("comparison");
      bool stopped = false;
      // Inside a cell only cancellation is forwarded: the cell's own stages are not this call's.
      const Progress cell = [&](const char*, double) {
        stopped = !report(progress, "compare", done);
        return !stopped;
      };
      ParamOptions options;
      options.source = resolved;
      options.boundary = boundary;
      options.weights = weight;
      options.solver = solver;
      ComparisonRow row;
      row.boundary = boundary;
      row.weights = weight;
      const Stopwatch time;
      auto p = parameterize(mesh, options, progress ? cell : Progress());
      row.timeMs = time.ms();
      if (stopped) return cancelledError("comparison");
      if (p) {
        const StretchMetrics& m = p.value().metrics;
        row.l2 = m.l2;
        row.linf = m.linf;
        row.flipped = m.flipped;
        row.degenerate = m.degenerate;
        row.bijective = m.bijective;
        const auto i = static_cast<int64_t>(comparison.rows.size());
        const ComparisonRow* best = comparison.best >= 0 ? &comparison.rows[comparison.best] : nullptr;
        if (!best || preferredMap(row.l2, row.flipped + row.degenerate, best->l2, best->flipped + best->degenerate))
          comparison.best = i;
      } else {
        if (p.error().code == ErrorCode::Cancelled) return p.error();
        row.error = p.error();
      }
      comparison.rows.push_back(std::move(row));
    }
  report(progress, "compare", 1.0);
  return comparison;
}

}  // namespace straightest
