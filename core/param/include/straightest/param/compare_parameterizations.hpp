// compare_parameterizations.hpp — every boundary kind × every weight kind of one mesh, parameterized
// and judged side by side, with the best row picked by preferredMap (the rule boundary 'auto' uses).
// What the page's comparison table shows. A free row refines the map its weights' measured (if
// bijective) or circle row already solved, as parameterize with boundary free would (no second solve).
#pragma once
#include <optional>
#include <vector>

#include "straightest/param/parameterize.hpp"

namespace straightest {

struct ComparisonRow {
  BoundaryKind boundary = BoundaryKind::Measured;
  WeightKind weights = WeightKind::ShapePreserving;
  double l2 = 0, linf = 0;  // +inf when not bijective
  int64_t flipped = 0, degenerate = 0;
  int64_t overlaps = 0;  // crossing pairs of boundary edges
  bool bijective = false;
  // free rows: the refinement's start (measured or circle), iterations and stopping reason; nullopt
  // (and the rest meaningless) for a fixed boundary
  std::optional<BoundaryKind> init;
  int32_t iterations = 0;
  bool converged = false;
  double timeMs = 0;           // wall time of this cell's parameterization (what the table compares); a free
                               // row counts its start's solve(s) too, as parameterize with boundary free would
  std::optional<Error> error;  // this cell failed (no numbers); e.g. measured with no interior source
};

struct Comparison {
  std::vector<ComparisonRow> rows;  // boundary-major: for each boundary, every weights in order
  int64_t best = -1;                // index into rows by preferredMap over the rows without error; -1 if none
};

/// The source is resolved once (nullopt: the default source) and shared by every cell. A mesh that is
/// not a disk is cut (or filled) by each cell's parameterize the same way (cutToDisk is deterministic),
/// with the disk's default source; a cell that cannot be parameterized keeps its error. Progress stage "compare": the
/// fraction of cells done; cancelling (at any point, also inside a cell) returns a Cancelled error. `free`: the
/// refinement's options for free rows.
Expected<Comparison> compareParameterizations(const TriMesh& mesh, const std::optional<SurfacePoint>& source,
                                              const std::vector<BoundaryKind>& boundaries,
                                              const std::vector<WeightKind>& weights,
                                              LinearSolver solver = LinearSolver::Multigrid,
                                              const Progress& progress = {}, const FreeBoundaryOptions& free = {});

}  // namespace straightest
