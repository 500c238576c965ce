// free_boundary.hpp — a free-boundary map that never folds. Starting from a fixed-boundary map (the
// caller's choice: the measured boundary where its map is bijective, otherwise the circle), every
// vertex, boundary included, moves to lower an isometric distortion energy: the symmetric Dirichlet
// energy, Σ_t A_t (‖J_t‖²_F + ‖J_t⁻¹‖²_F) / Σ_t A_t, which is 4 exactly for an isometry and infinite
// for a flipped or zero-area triangle. The start is first scaled to the energy's best scale
// (E(s) = s² A + B / s², s⁴ = B / A), so energyInitial measures shape, not size.
//
// Why SLIM (Rabinovich et al. 2017, "Scalable locally injective mappings"): each iteration is a local
// step (per face, J's closest rotation and a weight from its singular values) and a global step (one
// sparse symmetric solve over all vertices), so it converges in tens of iterations where gradient
// descent needs thousands, and its cost per iteration is one linear solve (slim_global_step.hpp:
// sparse Cholesky on small meshes, multigrid-preconditioned conjugate gradients on large ones). Our
// weight multiplies J from the face's side (‖(J − R) M^½‖, not ‖W (J − R)‖): the value and gradient at
// the current map are SLIM's, and u and v share one matrix, half the size of SLIM's coupled system.
//
// The line search is the guarantee. The step along the global step's direction is at most 0.8 of the
// first t at which any face's signed area (a quadratic in t) reaches zero, then halved until the energy
// falls by the Armijo rule, every face keeps its 2D area above texture stretch's degeneracy threshold
// (kDegenerateUV × the mean) and the boundary crosses itself no more often than the start's
// (boundaryOverlaps; a convex start has none). Every accepted map therefore keeps the start's
// bijectivity: a start with no flipped, no degenerate face and no overlap yields a result with none,
// whatever the iteration count, the time budget or the mesh. A step that cannot satisfy all three ends
// the refinement (converged: no descent is left within the constraints).
//
// Untangling: a start with flipped or degenerate faces (convex-combination maps of long protrusions
// underflow in floating point; a boundary ear can collapse) has infinite energy, so SLIM cannot start
// from it. It is first untangled with the boundary held at the start's convex polygon, where an
// injective map exists (Tutte), by minimizing the regularized barrier of Garanzha et al. 2021
// ("Foldover-free maps in 50 lines of code") with L-BFGS and continuation on its ε (untangle.hpp);
// SLIM then frees the boundary. If untangling fails (time budget, or a map no barrier can repair) the
// best map comes back with untangled = true and energyFinal = +∞, and the caller's texture stretch
// reports it as not bijective, with counts. (A start that is a mirror image, its faces clockwise by
// total signed area, is mirrored back first: that needs no untangling.)
//
// Zero-area 3D faces (TriMesh::isDegenerateFace) carry no area and so no energy: they are left out of
// the energy and the global step, yet the line search still keeps their 2D area positive; untangling
// gives them an equilateral shape of the mean face area to aim for. No NaN comes from them.
//
// The energy fixes the map's scale (an isometry has its 3D size); the caller normalizes uv for
// display, and texture stretch is scale-invariant as ever.
#pragma once
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

struct FreeBoundaryOptions {
  int32_t maxIterations = 200;      // SLIM iterations (untangling has its own caps)
  double relativeTolerance = 1e-5;  // stop when one iteration lowers the energy by less than this fraction
  double timeBudgetMs = 60000;      // untangling and refinement together; then stop with converged = false
                                    // and the best map so far (bijective when the start was or untangled)
};

struct FreeBoundaryResult {
  std::vector<Vec2> uv;  // per vertex (unreferenced vertices: (0, 0)), at the energy's isometric scale
  int32_t iterations = 0;
  double energyInitial = 0;  // symmetric Dirichlet per unit 3D area of the (rescaled) start; +inf if it folds
  double energyFinal = 0;    // of the result: 4 for an isometry
  bool converged = false;    // the relative-decrease rule stopped it, or no step was left that lowers the
                             // energy within the constraints (not the iteration cap or the time budget)
  bool untangled = false;    // the start had flipped or degenerate triangles and was untangled first
};

/// `mesh` is a disk, or a disk with holes (parameterize refines the real faces of a filled disk, its holes
/// left free; the caller checks): what the guarantee needs is a start with no flipped or degenerate face
/// and no crossing between any two boundary edges of any loops. Such a map is injective on a disk with
/// holes too: the number of preimages of a point is the winding number of the outer loop's image (0 or
/// 1) plus the holes' (0 or −1, their loops run clockwise), so at most 1; and the line search keeps all
/// three conditions over every loop. Untangling holds every boundary vertex, the holes' rims included.
/// `start` has one uv per vertex. Progress stage "refine"
/// (fraction by iteration; when the start is untangled first, untangling is its first half). Errors:
/// InvalidArgument (start of the wrong size or not finite at a vertex of a face, negative options),
/// Cancelled.
/// When untangling fails the result still comes back (with its flipped triangles): the caller's
/// texture stretch then reports it as not bijective, with counts.
Expected<FreeBoundaryResult> refineFreeBoundary(const TriMesh& mesh, const std::vector<Vec2>& start,
                                                const FreeBoundaryOptions& options = {}, const Progress& progress = {});

}  // namespace straightest
