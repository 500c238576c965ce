// free_boundary.hpp — a free-boundary map that never folds. Starting from a fixed-boundary map (the
// caller's choice: the measured boundary where its map is bijective, otherwise the circle), every
// vertex, boundary included, moves to lower an isometric distortion energy: the symmetric Dirichlet
// energy, Σ_t A_t (‖J_t‖²_F + ‖J_t⁻¹‖²_F) / Σ_t A_t, which is 4 exactly for an isometry and infinite
// for a flipped or zero-area triangle. Each step is a local-global iteration (SLIM, Rabinovich et al.
// 2017) whose line search never lets a triangle's 2D area reach zero, so a start without flipped or
// degenerate triangles stays that way. A start that has them (linear maps underflow on thin
// protrusions) is first untangled (regularized barrier with continuation on ε, Garanzha et al. 2021).
//
// The energy fixes the map's scale (an isometry has its 3D size); the caller normalizes uv for
// display, and texture stretch is scale-invariant as ever.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/error.hpp"
#include "straightest/progress.hpp"
#include "straightest/trimesh.hpp"

namespace straightest {

struct FreeBoundaryOptions {
  int32_t maxIterations = 200;      // refinement iterations (untangling has its own cap)
  double relativeTolerance = 1e-5;  // stop when one iteration lowers the energy by less than this fraction
  double timeBudgetMs = 60000;      // stop after this long with converged = false (the best map so far)
};

struct FreeBoundaryResult {
  std::vector<Vec2> uv;  // per vertex (unreferenced vertices: (0, 0)), at the energy's isometric scale
  int32_t iterations = 0;
  double energyInitial = 0;  // symmetric Dirichlet per unit 3D area of the (rescaled) start; +inf if it folds
  double energyFinal = 0;    // of the result: 4 for an isometry
  bool converged = false;    // the relative-decrease rule stopped it (not the iteration cap or the time budget)
  bool untangled = false;    // the start had flipped or degenerate triangles and was untangled first
};

/// `mesh` must be a disk (the caller checks); `start` has one uv per vertex. Progress stage "refine"
/// (fraction by iteration). Errors: InvalidArgument (start of the wrong size or not finite), Cancelled.
/// When untangling fails the result still comes back (with its flipped triangles): the caller's
/// texture stretch then reports it as not bijective, with counts.
Expected<FreeBoundaryResult> refineFreeBoundary(const TriMesh& mesh, const std::vector<Vec2>& start,
                                                const FreeBoundaryOptions& options = {}, const Progress& progress = {});

}  // namespace straightest
