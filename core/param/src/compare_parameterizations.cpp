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

/// A row's result: its metrics, or its error (a cancellation is not a row's error: it ends the
/// comparison).
Expected<void> record(ComparisonRow& row, const Expected<Parameterization>& p) {
  if (p) fillMetrics(row, p.value());
  else if (p.error().code == ErrorCode::Cancelled) return p.error();
  else row.error = p.error();
  return {};
}

/// The comparison's cells, filled weights by weights, so that a free row finds its start among the
/// maps of its own weights and only those (two at most) are kept alive at a time.
class Comparer {
 public:
  Comparer(const TriMesh& mesh, const Progress& progress, const FreeBoundaryOptions& free, double cells)
      : mesh_(mesh), progress_(progress), free_(free), cells_(cells) {}

  /// Fills the rows of one weights (one per boundary), starting fresh maps for it.
  Expected<void> fillWeights(const ParamOptions& options, const std::vector<BoundaryKind>& boundaries,
                             ComparisonRow* const* rows) {
    options_ = options;
    measured_ = Solved{};
    circle_ = Solved{};
    const bool wantsFree = std::find(boundaries.begin(), boundaries.end(), BoundaryKind::Free) != boundaries.end();
    for (size_t b = 0; b < boundaries.size(); ++b) {
      if (!report(progress_, "compare", done_ / cells_)) return cancelledError("comparison");
      ComparisonRow& row = *rows[b];
      row.boundary = boundaries[b];
      row.weights = options.weights;
      auto filled = row.boundary == BoundaryKind::Free ? freeRow(row) : fixedRow(row, wantsFree);
      if (!filled) return filled;
      ++done_;
    }
    return {};
  }

 private:
  /// Inside a cell only cancellation is forwarded: the cell's own stages are not this call's.
  Progress cellProgress() {
    if (!progress_) return Progress();
    const double at = done_ / cells_;
    return Progress([this, at](const char*, double) {
      stopped_ = !report(progress_, "compare", at);
      return !stopped_;
    });
  }

  Solved& fixedMap(BoundaryKind kind) {
    Solved& s = kind == BoundaryKind::Measured ? measured_ : circle_;
    if (!s.done) {
      ParamOptions o = options_;
      o.boundary = kind;
      const Stopwatch time;
      s.map = parameterize(mesh_, o, cellProgress());
      s.ms = time.ms();
      s.done = true;
      if (s.map) s.map.value().metrics.faceStretch = {};  // not needed by the rows; a free row keeps uv only
    }
    return s;
  }

  /// A row of a fixed boundary; the measured and circle maps are kept when a free row may start from them.
  Expected<void> fixedRow(ComparisonRow& row, bool wantsFree) {
    if (wantsFree && (row.boundary == BoundaryKind::Measured || row.boundary == BoundaryKind::Circle)) {
      const Solved& s = fixedMap(row.boundary);
      row.timeMs = s.ms;
      if (stopped_) return cancelledError("comparison");
      return record(row, s.map);
    }
    ParamOptions o = options_;
    o.boundary = row.boundary;
    const Stopwatch time;
    const Expected<Parameterization> own = parameterize(mesh_, o, cellProgress());
    row.timeMs = time.ms();
    if (stopped_) return cancelledError("comparison");
    return record(row, own);
  }

  /// parameterize's rule for free: an interior source, then the measured map if bijective, else the
  /// circle's, refined.
  Expected<void> freeRow(ComparisonRow& row) {
    auto s = interiorSource(mesh_, options_.source);
    if (!s) {
      row.error = s.error();
      return {};
    }
    const Solved* start = &fixedMap(BoundaryKind::Measured);
    if (stopped_) return cancelledError("comparison");
    double ms = start->ms;
    if (!start->map || !start->map.value().metrics.bijective) {
      start = &fixedMap(BoundaryKind::Circle);
      if (stopped_) return cancelledError("comparison");
      ms += start->ms;
    }
    if (!start->map) return record(row, start->map);
    const Stopwatch time;
    auto p = refineParameterization(mesh_, start->map.value(), free_, cellProgress());
    row.timeMs = ms + time.ms();
    if (stopped_) return cancelledError("comparison");
    return record(row, p);
  }

  const TriMesh& mesh_;
  const Progress& progress_;
  const FreeBoundaryOptions& free_;
  const double cells_;
  double done_ = 0;
  bool stopped_ = false;
  ParamOptions options_;
  Solved measured_, circle_;
};

/// The row preferredMap chooses among those without an error (-1 if none).
int64_t bestRow(const std::vector<ComparisonRow>& rows) {
  int64_t best = -1;
  for (size_t i = 0; i < rows.size(); ++i) {
    const ComparisonRow& row = rows[i];
    if (row.error) continue;
    const ComparisonRow* b = best >= 0 ? &rows[best] : nullptr;
    if (!b || preferredMap(row.l2, row.flipped + row.degenerate, b->l2, b->flipped + b->degenerate))
      best = static_cast<int64_t>(i);
  }
  return best;
}

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
  const size_t nb = boundaries.size(), nw = weights.size();
  Comparison comparison;
  comparison.rows.resize(nb * nw);  // boundary-major
  Comparer comparer(mesh, progress, free, static_cast<double>(nb * nw));
  std::vector<ComparisonRow*> column(nb);
  for (size_t w = 0; w < nw; ++w) {
    ParamOptions options;
    options.source = resolved;
    options.weights = weights[w];
    options.solver = solver;
    for (size_t b = 0; b < nb; ++b) column[b] = &comparison.rows[b * nw + w];
    if (auto filled = comparer.fillWeights(options, boundaries, column.data()); !filled) return filled.error();
  }
  comparison.best = bestRow(comparison.rows);
  report(progress, "compare", 1.0);
  return comparison;
}

}  // namespace straightest
