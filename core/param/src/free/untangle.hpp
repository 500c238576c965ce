// untangle.hpp — making a map with flipped or zero-area triangles injective, its fixed vertices held
// in place (a convex boundary polygon: Tutte's theorem says an injective map then exists, but a linear
// solve in floating point can still underflow or fold along thin protrusions). Minimizes the
// regularized barrier of Garanzha et al. 2021 ("Foldover-free maps in 50 lines of code"): per face,
// with J the Jacobian relative to the face's 3D shape scaled to the polygon's area and
// χ(D, ε) = (D + √(ε² + D²)) / 2 a smooth positive stand-in for D = det J,
//     f = (1 − θ) ‖J‖²_F / χ(D, ε) + θ (D² + 1) / χ(D, ε),
// finite for every map when ε > 0 and tending to a barrier against D ≤ 0 as ε → 0. Each round
// minimizes it with L-BFGS at fixed ε (its initial inverse Hessian the inverse cotan Laplacian of the
// 3D shape: with the identity, thin protrusions whose map had underflowed stayed folded for every round
// allowed; with the Laplacian they untangle in a few rounds), then lowers ε by the paper's rule (from the
// smallest D and the round's energy decrease), until every face is positive by a margin. It stops there: the refinement
// that follows needs positive faces, not good ones (going on until the smallest face is 1e-3 of its ideal size takes
// many more rounds, and SLIM ends at about the same energy either way). Private to the free-boundary refinement.
#pragma once
#include <chrono>
#include <cstdint>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

struct UntangleResult {
  std::vector<Vec2> uv;
  bool injective = false;  // every face's signed area above kUntangledArea × the mean
  int32_t iterations = 0;  // L-BFGS iterations over all rounds
};

/// The margin an untangled map keeps: every face's 2D area above this fraction of the mean. Far above
/// texture stretch's degeneracy threshold, so the refinement that follows starts with finite energy.
inline constexpr double kUntangledArea = 1e-8;

/// Moves every vertex with fixed[v] == 0. Progress stage "refine" (fraction by round). Stops at the
/// deadline with the map so far (injective false unless it already is). Errors: Cancelled.
Expected<UntangleResult> untangle(const TriMesh& mesh, std::vector<Vec2> uv, const std::vector<uint8_t>& fixed,
                                  std::chrono::steady_clock::time_point deadline, const Progress& progress);

/// True when every face's signed area exceeds `margin` × the mean |area| (and is finite).
bool allFacesPositive(const TriMesh& mesh, const std::vector<Vec2>& uv, double margin);

}  // namespace straightest
