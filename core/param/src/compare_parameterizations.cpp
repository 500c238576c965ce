// compare_parameterizations.cpp — every boundary × weights side by side, and the best by preferredMap.
#include "straightest/param/compare_parameterizations.hpp"

#include <algorithm>

#include "straightest/geodesics/geodesic_distance.hpp"

namespace straightest {
namespace {

void fillMetrics(ComparisonRow& row, const Parameterization& p) {
  const StretchMetrics& m = p.metrics;
  row.l2 = m.l2;
  row.linf = m.linf;
  row.flipped = m.flipped;
  row.degenerate = m.degenerate;
  row.overlaps = m.overlaps;
  row.bijective = m.bijective;
  row.init = p.init;
  row.iterations = p.iterations;
  row.converged = p.converged;
}

/// A fixed map of one weights, kept for the free row that may start from it, with its time.
struct Solved {
  Expected<Parameterization> map = Error{ErrorCode::Internal, "not solved"};
  double ms = 0;
  bool done = false;
};

}  // namespace

Expected<Comparison> compareParameterizations(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                              const std::vector<BoundaryKind>& boundaries,
                                              const std::vector<WeightKind>& weights, LinearSolver solver,
                                              const Progress& progress, const FreeBoundaryOptions& free) {
  // One source for every cell; one the measured boundary cannot use fails those cells only. A mesh that
  // is not a disk is cut in every cell (the same cut each time): its default source is the disk's.
  std::optional<SurfacePoint> resolved = source;
  if (!source && requireDisk(mesh)) {
    auto s = resolveSource(mesh, std::nullopt);
    if (s) resolved = s.value();
  }
  const bool wantsFree = std::find(boundaries.begin(), boundaries.end(), BoundaryKind::Free) != boundaries.end();
  const size_t nb = boundaries.size(), nw = weights.size();
  const double cells = static_cast<double>(nb * nw);
  std::vector<ComparisonRow> grid(nb * nw);  // boundary-major, filled weights by weights
  size_t done = 0;
  bool stopped = false;
  // Inside a cell only cancellation is forwarded: the cell's own stages are not this call's.
  auto cellProgress = [&]() -> Progress {
    if (!progress) return Progress();
    const double at = static_cast<double>(done) / cells;
    return Progress([&progress, &stopped, at](const char*, double) {
      stopped = !report(progress, "compare", at);
      return !stopped;
    });
  };
  // Weights by weights, so that a free row finds its start among the maps of its own weights and
  // only those (two at most) are kept alive at a time.
  for (size_t w = 0; w < nw; ++w) {
    Solved measured, circle;
    ParamOptions options;
    options.source = resolved;
    options.weights = weights[w];
    options.solver = solver;
    auto fixedMap = [&](BoundaryKind kind) -> Solved& {
      Solved& s = kind == BoundaryKind::Measured ? measured : circle;
      if (!s.done) {
        ParamOptions o = options;
        o.boundary = kind;
        const Stopwatch time;
        s.map = parameterize(mesh, o, cellProgress());
        s.ms = time.ms();
        s.done = true;
        if (s.map) s.map.value().metrics.faceStretch = {};  // not needed by the rows; a free row keeps uv only
      }
      return s;
    };
    for (size_t b = 0; b < nb; ++b) {
      if (!report(progress, "compare", static_cast<double>(done) / cells)) return cancelledError("comparison");
      ComparisonRow& row = grid[b * nw + w];
      row.boundary = boundaries[b];
      row.weights = weights[w];
      if (row.boundary != BoundaryKind::Free) {
        Expected<Parameterization> own = Error{ErrorCode::Internal, "not solved"};
        const Expected<Parameterization>* p = &own;
        if (wantsFree && (row.boundary == BoundaryKind::Measured || row.boundary == BoundaryKind::Circle)) {
          const Solved& s = fixedMap(row.boundary);  // kept for the free row
          p = &s.map;
          row.timeMs = s.ms;
        } else {
          options.boundary = row.boundary;
          const Stopwatch time;
          own = parameterize(mesh, options, cellProgress());
          row.timeMs = time.ms();
        }
        if (stopped) return cancelledError("comparison");
        if (*p) fillMetrics(row, p->value());
        else if (p->error().code == ErrorCode::Cancelled) return p->error();
        else row.error = p->error();
      } else {
        // parameterize's rule for free: an interior source, then the measured map if bijective, else
        // the circle's, refined.
        auto s = interiorSource(mesh, resolved);
        if (!s) {
          row.error = s.error();
        } else {
          const Solved* start = &fixedMap(BoundaryKind::Measured);
          if (stopped) return cancelledError("comparison");
          double ms = start->ms;
          if (!start->map || !start->map.value().metrics.bijective) {
            start = &fixedMap(BoundaryKind::Circle);
            if (stopped) return cancelledError("comparison");
            ms += start->ms;
          }
          if (!start->map) {
            if (start->map.error().code == ErrorCode::Cancelled) return start->map.error();
            row.error = start->map.error();
          } else {
            const Stopwatch time;
            auto p = refineParameterization(mesh, start->map.value(), free, cellProgress());
            row.timeMs = ms + time.ms();
            if (stopped) return cancelledError("comparison");
            if (p) fillMetrics(row, p.value());
            else if (p.error().code == ErrorCode::Cancelled) return p.error();
            else row.error = p.error();
          }
        }
      }
      ++done;
    }
  }
  Comparison comparison;
  comparison.rows = std::move(grid);
  for (size_t i = 0; i < comparison.rows.size(); ++i) {
    const ComparisonRow& row = comparison.rows[i];
    if (row.error) continue;
    const ComparisonRow* best = comparison.best >= 0 ? &comparison.rows[comparison.best] : nullptr;
    if (!best || preferredMap(row.l2, row.flipped + row.degenerate, best->l2, best->flipped + best->degenerate))
      comparison.best = static_cast<int64_t>(i);
  }
  report(progress, "compare", 1.0);
  return comparison;
}

}  // namespace straightest
