// free_boundary.cpp — SLIM refinement with the boundary free; its line search is the no-fold guarantee.
#include "straightest/param/free_boundary.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "slim_global_step.hpp"
#include "straightest/param/boundary_overlaps.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "symmetric_dirichlet.hpp"
#include "untangle.hpp"

namespace straightest {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kFlipMargin = 0.8;     // of the largest step before a face would flip
constexpr double kArmijo = 1e-4;        // sufficient decrease, as a fraction of the slope
constexpr int kMaxHalvings = 40;        // then no step lowers the energy: a stationary point
constexpr double kUntangleShare = 0.5;  // of the "refine" progress, when the start must be untangled

/// The texture-stretch rule: a face with 2D area ≤ kDegenerateUV × mean |area| (or negative) is bad.
bool hasBadFace(const TriMesh& mesh, const std::vector<Vec2>& uv) { return !allFacesPositive(mesh, uv, kDegenerateUV); }

/// The energy per unit area and its derivative along `direction` (per unit area too).
struct EnergySlope {
  double energy, slope;
};
EnergySlope energyAndSlope(const TriMesh& mesh, const std::vector<FaceGradient>& gradients, const std::vector<Vec2>& uv,
                           const std::vector<Vec2>& direction) {
  double sum = 0, slope = 0, area = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const FaceGradient& g = gradients[f];
    if (!(g.area > 0)) continue;
    const Mat2 j = jacobian(g, mesh.triangle(f), uv), dj = jacobian(g, mesh.triangle(f), direction);
    const Mat2 p = symmetricDirichletGradient(j);
    sum += g.area * symmetricDirichlet(j);
    slope += g.area * (p.a * dj.a + p.b * dj.b + p.c * dj.c + p.d * dj.d);
    area += g.area;
  }
  return {sum / area, slope / area};
}

double energyOf(const TriMesh& mesh, const std::vector<FaceGradient>& gradients, const std::vector<Vec2>& uv) {
  return dirichletSums(mesh, gradients, uv).perUnitArea();
}

/// uv scaled about the origin to the scale of least energy: E(s) = s² direct + inverse / s², s⁴ = inverse / direct.
void rescale(const TriMesh& mesh, const std::vector<FaceGradient>& gradients, std::vector<Vec2>& uv) {
  const DirichletSums sums = dirichletSums(mesh, gradients, uv);
  const double s = std::pow(sums.inverse / sums.direct, 0.25);
  if (!std::isfinite(s) || !(s > 0)) return;
  for (Vec2& q : uv) q *= s;
}

}  // namespace

Expected<FreeBoundaryResult> refineFreeBoundary(const TriMesh& mesh, const std::vector<Vec2>& start,
                                                const FreeBoundaryOptions& options, const Progress& progress) {
  const Clock::time_point began = Clock::now();
  if (static_cast<int64_t>(start.size()) != mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, "the start map needs one uv per vertex (" +
                                                 std::to_string(mesh.numVertices()) + "), got " +
                                                 std::to_string(start.size())};
  std::vector<uint8_t> referenced(mesh.numVertices(), 0);
  for (const Triangle& t : mesh.triangles())
    for (int32_t v : t) referenced[v] = 1;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (referenced[v] && !isFinite(start[v]))
      return Error{ErrorCode::InvalidArgument, "the start map is not finite at vertex " + std::to_string(v)};
  if (!(options.maxIterations >= 0) || !(options.relativeTolerance >= 0) || !(options.timeBudgetMs >= 0))
    return Error{ErrorCode::InvalidArgument,
                 "the refinement's iteration cap, tolerance and time budget must not be negative"};
  const Clock::time_point deadline = began + std::chrono::duration_cast<Clock::duration>(
                                                 std::chrono::duration<double, std::milli>(
                                                     std::min(options.timeBudgetMs, 1e12)));

  FreeBoundaryResult result;
  std::vector<Vec2> uv(start);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (!referenced[v]) uv[v] = {0, 0};
  // A mirror image (every face clockwise) is as injective as its mirror: flip it rather than untangle it.
  double signedArea = 0;
  for (const Triangle& t : mesh.triangles()) signedArea += twiceSignedArea(t, uv);
  if (signedArea < 0)
    for (Vec2& q : uv) q.x = -q.x;
  const std::vector<FaceGradient> gradients = faceGradients(mesh, false);
  Progress slimProgress = progress;
  if (hasBadFace(mesh, uv) || !std::isfinite(energyOf(mesh, gradients, uv))) {
    // Untangle with the boundary held where the start put it (a convex polygon), except the corners of
    // a collapsed boundary ear (a bad face with all three corners on the boundary: nothing else could
    // open it).
    std::vector<uint8_t> fixed(mesh.numVertices(), 0);
    for (int32_t v = 0; v < mesh.numVertices(); ++v) fixed[v] = mesh.isBoundaryVertex(v) || !referenced[v];
    double meanArea = 0;
    for (const Triangle& t : mesh.triangles()) meanArea += std::abs(twiceSignedArea(t, uv));
    meanArea /= std::max(1, mesh.numFaces());
    for (const Triangle& t : mesh.triangles())
      if (!(twiceSignedArea(t, uv) > kDegenerateUV * meanArea) && fixed[t[0]] && fixed[t[1]] && fixed[t[2]])
        for (int32_t v : t) fixed[v] = 0;
    auto untangled = untangle(mesh, std::move(uv), fixed, deadline, progress.range(0, kUntangleShare));
    if (!untangled) return untangled.error();
    uv = std::move(untangled.value().uv);
    result.untangled = true;
    result.energyInitial = std::numeric_limits<double>::infinity();
    slimProgress = progress.range(kUntangleShare, 1);
    if (hasBadFace(mesh, uv) || !std::isfinite(energyOf(mesh, gradients, uv))) {
      result.uv = std::move(uv);  // untangling failed: the caller's texture stretch reports the counts
      result.energyFinal = std::numeric_limits<double>::infinity();
      return result;
    }
  }
  rescale(mesh, gradients, uv);
  double energy = energyOf(mesh, gradients, uv);
  if (!result.untangled) result.energyInitial = energy;
  const int64_t allowedOverlaps = boundaryOverlaps(mesh, uv);

  ThrottledProgress report(slimProgress, "refine");
  SlimGlobalStep global(mesh);
  std::vector<Mat2> weights(mesh.numFaces()), rotations(mesh.numFaces());
  std::vector<Vec2> next, direction(uv.size()), trial(uv.size());
  for (; result.iterations < options.maxIterations; ++result.iterations) {
    if (!report(double(result.iterations) / std::max(1, options.maxIterations)))
      return cancelledError("parameterization");
    if (Clock::now() > deadline) break;
    for (int32_t f = 0; f < mesh.numFaces(); ++f)
      if (gradients[f].area > 0) slimLocalStep(jacobian(gradients[f], mesh.triangle(f), uv), weights[f], rotations[f]);
    if (!global.solve(gradients, weights, rotations, uv, next)) break;
    for (size_t i = 0; i < uv.size(); ++i) direction[i] = next[i] - uv[i];
    // Line search: never past 0.8 of the first flip; then halve until the energy falls enough, every face
    // stays above the degeneracy threshold and the boundary crosses itself no more than the start's.
    const EnergySlope here = energyAndSlope(mesh, gradients, uv, direction);
    if (!(here.slope < 0)) {
      result.converged = true;  // no descent left along SLIM's direction
      break;
    }
    double t = std::min(1.0, kFlipMargin * largestFlipFreeStep(mesh, uv, direction));
    bool accepted = false;
    double trialEnergy = energy;
    for (int halving = 0; halving < kMaxHalvings && !accepted; ++halving) {
      if (halving > 0) t *= 0.5;
      for (size_t i = 0; i < uv.size(); ++i) trial[i] = uv[i] + direction[i] * t;
      trialEnergy = energyOf(mesh, gradients, trial);
      accepted = std::isfinite(trialEnergy) && trialEnergy <= energy + kArmijo * t * here.slope &&
                 !hasBadFace(mesh, trial) && boundaryOverlaps(mesh, trial) <= allowedOverlaps;
    }
    if (!accepted) {
      result.converged = true;  // no step along the direction lowers the energy within the constraints
      break;
    }
    const double decrease = (energy - trialEnergy) / energy;
    uv.swap(trial);
    energy = trialEnergy;
    if (decrease < options.relativeTolerance) {
      ++result.iterations;
      result.converged = true;
      break;
    }
  }
  report(1);
  result.energyFinal = energy;
  result.uv = std::move(uv);
  return result;
}

}  // namespace straightest
