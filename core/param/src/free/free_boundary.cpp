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

/// The vertices some face uses (the others are given uv (0, 0) and never move).
std::vector<uint8_t> referencedVertices(const TriMesh& mesh) {
  std::vector<uint8_t> referenced(mesh.numVertices(), 0);
  for (const Triangle& t : mesh.triangles())
    for (int32_t v : t) referenced[v] = 1;
  return referenced;
}

Expected<void> checkArguments(const TriMesh& mesh, const std::vector<Vec2>& start,
                              const std::vector<uint8_t>& referenced, const FreeBoundaryOptions& options) {
  if (static_cast<int64_t>(start.size()) != mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, "the start map needs one uv per vertex (" +
                                                 std::to_string(mesh.numVertices()) + "), got " +
                                                 std::to_string(start.size())};
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (referenced[v] && !isFinite(start[v]))
      return Error{ErrorCode::InvalidArgument, "the start map is not finite at vertex " + std::to_string(v)};
  if (!(options.maxIterations >= 0) || !(options.relativeTolerance >= 0) || !(options.timeBudgetMs >= 0))
    return Error{ErrorCode::InvalidArgument,
                 "the refinement's iteration cap, tolerance and time budget must not be negative"};
  return {};
}

/// The start with unused vertices at the origin; a mirror image (every face clockwise) is as injective
/// as its mirror: it is flipped rather than untangled.
std::vector<Vec2> orientedStart(const TriMesh& mesh, const std::vector<Vec2>& start,
                                const std::vector<uint8_t>& referenced) {
  std::vector<Vec2> uv(start);
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (!referenced[v]) uv[v] = {0, 0};
  double signedArea = 0;
  for (const Triangle& t : mesh.triangles()) signedArea += twiceSignedArea(t, uv);
  if (signedArea < 0)
    for (Vec2& q : uv) q.x = -q.x;
  return uv;
}

/// Untangles uv with the boundary held where the start put it (a convex polygon), except the corners of
/// a collapsed boundary ear (a bad face with all three corners on the boundary: nothing else could open
/// it).
Expected<std::vector<Vec2>> untangleStart(const TriMesh& mesh, std::vector<Vec2> uv,
                                          const std::vector<uint8_t>& referenced, Clock::time_point deadline,
                                          const Progress& progress) {
  std::vector<uint8_t> fixed(mesh.numVertices(), 0);
  for (int32_t v = 0; v < mesh.numVertices(); ++v) fixed[v] = mesh.isBoundaryVertex(v) || !referenced[v];
  double meanArea = 0;
  for (const Triangle& t : mesh.triangles()) meanArea += std::abs(twiceSignedArea(t, uv));
  meanArea /= std::max(1, mesh.numFaces());
  for (const Triangle& t : mesh.triangles())
    if (!(twiceSignedArea(t, uv) > kDegenerateUV * meanArea) && fixed[t[0]] && fixed[t[1]] && fixed[t[2]])
      for (int32_t v : t) fixed[v] = 0;
  auto untangled = untangle(mesh, std::move(uv), fixed, deadline, progress);
  if (!untangled) return untangled.error();
  return std::move(untangled.value().uv);
}

/// SLIM's iterations from a map with every face positive: each takes SLIM's direction and a line
/// search that never passes 0.8 of the first flip, then halves until the energy falls enough, every
/// face stays above the degeneracy threshold and the boundary crosses itself no more than the start's.
class SlimDescent {
 public:
  SlimDescent(const TriMesh& mesh, const std::vector<FaceGradient>& gradients, std::vector<Vec2>& uv)
      : mesh_(mesh),
        gradients_(gradients),
        uv_(uv),
        global_(mesh),
        weights_(mesh.numFaces()),
        rotations_(mesh.numFaces()),
        direction_(uv.size()),
        trial_(uv.size()),
        allowedOverlaps_(boundaryOverlaps(mesh, uv)),
        energy_(energyOf(mesh, gradients, uv)) {}

  double energy() const { return energy_; }

  /// What an iteration did: moved uv (and by how much, relative to the tolerance), or found no descent
  /// within the constraints (a stationary point), or its global solve failed.
  enum class Step { Moved, MovedBelowTolerance, Stationary, SolveFailed };

  Step step(double tolerance) {
    for (int32_t f = 0; f < mesh_.numFaces(); ++f)
      if (gradients_[f].area > 0)
        slimLocalStep(jacobian(gradients_[f], mesh_.triangle(f), uv_), weights_[f], rotations_[f]);
    if (!global_.solve(gradients_, weights_, rotations_, uv_, next_)) return Step::SolveFailed;
    for (size_t i = 0; i < uv_.size(); ++i) direction_[i] = next_[i] - uv_[i];
    const EnergySlope here = energyAndSlope(mesh_, gradients_, uv_, direction_);
    if (!(here.slope < 0)) return Step::Stationary;  // no descent left along SLIM's direction
    double trialEnergy = energy_;
    if (!lineSearch(here.slope, trialEnergy)) return Step::Stationary;  // no step lowers the energy
    const double decrease = (energy_ - trialEnergy) / energy_;
    uv_.swap(trial_);
    energy_ = trialEnergy;
    return decrease < tolerance ? Step::MovedBelowTolerance : Step::Moved;
  }

 private:
  bool lineSearch(double slope, double& trialEnergy) {
    double t = std::min(1.0, kFlipMargin * largestFlipFreeStep(mesh_, uv_, direction_));
    for (int halving = 0; halving < kMaxHalvings; ++halving) {
      if (halving > 0) t *= 0.5;
      for (size_t i = 0; i < uv_.size(); ++i) trial_[i] = uv_[i] + direction_[i] * t;
      trialEnergy = energyOf(mesh_, gradients_, trial_);
      if (std::isfinite(trialEnergy) && trialEnergy <= energy_ + kArmijo * t * slope && !hasBadFace(mesh_, trial_) &&
          boundaryOverlaps(mesh_, trial_) <= allowedOverlaps_)
        return true;
    }
    return false;
  }

  const TriMesh& mesh_;
  const std::vector<FaceGradient>& gradients_;
  std::vector<Vec2>& uv_;
  SlimGlobalStep global_;
  std::vector<Mat2> weights_, rotations_;
  std::vector<Vec2> next_, direction_, trial_;
  const int64_t allowedOverlaps_;
  double energy_;
};

}  // namespace

Expected<FreeBoundaryResult> refineFreeBoundary(const TriMesh& mesh, const std::vector<Vec2>& start,
                                                const FreeBoundaryOptions& options, const Progress& progress) {
  const Clock::time_point began = Clock::now();
  const std::vector<uint8_t> referenced = referencedVertices(mesh);
  if (auto checked = checkArguments(mesh, start, referenced, options); !checked) return checked.error();
  const Clock::time_point deadline = began + std::chrono::duration_cast<Clock::duration>(
                                                 std::chrono::duration<double, std::milli>(
                                                     std::min(options.timeBudgetMs, 1e12)));

  FreeBoundaryResult result;
  std::vector<Vec2> uv = orientedStart(mesh, start, referenced);
  const std::vector<FaceGradient> gradients = faceGradients(mesh, false);
  Progress slimProgress = progress;
  if (hasBadFace(mesh, uv) || !std::isfinite(energyOf(mesh, gradients, uv))) {
    auto untangled = untangleStart(mesh, std::move(uv), referenced, deadline, progress.range(0, kUntangleShare));
    if (!untangled) return untangled.error();
    uv = std::move(untangled).value();
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
  SlimDescent descent(mesh, gradients, uv);
  if (!result.untangled) result.energyInitial = descent.energy();

  ThrottledProgress report(slimProgress, "refine");
  for (; result.iterations < options.maxIterations; ++result.iterations) {
    if (!report(double(result.iterations) / std::max(1, options.maxIterations)))
      return cancelledError("parameterization");
    if (Clock::now() > deadline) break;
    const SlimDescent::Step step = descent.step(options.relativeTolerance);
    if (step == SlimDescent::Step::Moved) continue;
    if (step == SlimDescent::Step::MovedBelowTolerance) ++result.iterations;  // it counts: uv moved
    result.converged = step != SlimDescent::Step::SolveFailed;
    break;
  }
  report(1);
  result.energyFinal = descent.energy();
  result.uv = std::move(uv);
  return result;
}

}  // namespace straightest
