#include "straightest/free_boundary.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "straightest/boundary_overlaps.hpp"
#include "straightest/texture_stretch.hpp"
#include "symmetric_dirichlet.hpp"
#include "untangle.hpp"

namespace straightest {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kFlipMargin = 0.8;         // of the largest step before a face would flip
constexpr double kArmijo = 1e-4;            // sufficient decrease, as a fraction of the slope
constexpr int kMaxHalvings = 40;            // then no step lowers the energy: a stationary point
constexpr double kProximalRel = 1e-8;       // × the mean diagonal: pins the translation, changes little else
constexpr double kUntangleShare = 0.5;      // of the "refine" progress, when the start must be untangled
constexpr double kSolveReduction = 1e-6;    // conjugate gradients: residual reduction from the warm start
constexpr int kStaleFactorIterations = 20;  // more conjugate-gradient iterations than this: refactorize
constexpr int kMaxConjugateGradient = 60;   // then factorize the current matrix and solve directly

/// Calls the progress at most ~100 times: only when the fraction has moved by a hundredth.
class Reporter {
 public:
  explicit Reporter(const Progress& p) : progress_(p) {}
  bool operator()(double fraction) {
    if (fraction < last_ + 0.01) return true;
    last_ = fraction;
    return progress_("refine", fraction);
  }

 private:
  const Progress& progress_;
  double last_ = -1;
};

/// The texture-stretch rule: a face with 2D area ≤ kDegenerateUV × mean |area| (or negative) is bad.
bool hasBadFace(const TriMesh& mesh, const std::vector<Vec2>& uv) { return !allFacesPositive(mesh, uv, kDegenerateUV); }

/// SLIM's global step: Σ_f A_f (G_f x − r_f)ᵀ M_f (G_f x − r_f) for x = u and for x = v, one matrix
/// for both (the weights act in each face's 3D frame, see the header), plus a tiny proximal term
/// toward the current map that pins the translation. The pattern is analysed once. A factorization
/// is reused across iterations as the preconditioner of conjugate gradients started from the current
/// map (the weights change little from one iteration to the next); it is renewed when that takes
/// more than kStaleFactorIterations.
class GlobalStep {
 public:
  explicit GlobalStep(const TriMesh& mesh) : mesh_(mesh), n_(mesh.numVertices()) {
    std::vector<Eigen::Triplet<double>> pattern;
    pattern.reserve(9 * size_t(mesh.numFaces()) + n_);
    for (const Triangle& t : mesh.triangles())
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) pattern.emplace_back(t[r], t[c], 0.0);
    for (int32_t v = 0; v < n_; ++v) pattern.emplace_back(v, v, 0.0);
    matrix_.resize(n_, n_);
    matrix_.setFromTriplets(pattern.begin(), pattern.end());
    matrix_.makeCompressed();
    slots_.resize(9 * size_t(mesh.numFaces()));
    for (int32_t f = 0; f < mesh.numFaces(); ++f) {
      const Triangle& t = mesh.triangle(f);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) slots_[9 * size_t(f) + 3 * r + c] = slot(t[r], t[c]);
    }
    diagonal_.resize(n_);
    for (int32_t v = 0; v < n_; ++v) diagonal_[v] = slot(v, v);
    factor_.analyzePattern(matrix_);
  }

  /// The next map from `uv`, each face's weight M_f and target rotation; false when the matrix cannot
  /// be factorized (not finite).
  bool solve(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
             const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv, std::vector<Vec2>& next) {
    assemble(gradients, weights, rotations, uv);
    Eigen::MatrixX2d x(n_, 2);
    for (int32_t v = 0; v < n_; ++v) x.row(v) << uv[v].x, uv[v].y;
    bool solved = false;
    if (factored_) {
      const int iterations = conjugateGradients(x);
      solved = iterations >= 0;
      factored_ = solved && iterations <= kStaleFactorIterations;
    }
    if (!solved) {
      factor_.factorize(matrix_);
      if (factor_.info() != Eigen::Success) return false;
      factored_ = true;
      x = factor_.solve(rhs_);
    }
    next.resize(n_);
    for (int32_t v = 0; v < n_; ++v) next[v] = {x(v, 0), x(v, 1)};
    return x.allFinite();
  }

 private:
  int32_t slot(int32_t row, int32_t col) const {
    const int* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col];
    const int* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col + 1];
    return static_cast<int32_t>(std::lower_bound(begin, end, row) - matrix_.innerIndexPtr());
  }

  void assemble(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
                const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv) {
    double* value = matrix_.valuePtr();
    std::fill(value, value + matrix_.nonZeros(), 0.0);
    rhs_ = Eigen::MatrixX2d::Zero(n_, 2);
    for (int32_t f = 0; f < mesh_.numFaces(); ++f) {
      const FaceGradient& g = gradients[f];
      if (!(g.area > 0)) continue;
      const Mat2& m = weights[f];
      const Mat2& rot = rotations[f];
      const Triangle& t = mesh_.triangle(f);
      // M ∇φ_k per corner, then A ∇φ_rᵀ M ∇φ_c into the matrix and A ∇φ_rᵀ M (row of R) into each column.
      double mgx[3], mgy[3];
      for (int k = 0; k < 3; ++k) {
        mgx[k] = m.a * g.gx[k] + m.b * g.gy[k];
        mgy[k] = m.c * g.gx[k] + m.d * g.gy[k];
      }
      const size_t base = 9 * size_t(f);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) value[slots_[base + 3 * r + c]] += g.area * (g.gx[r] * mgx[c] + g.gy[r] * mgy[c]);
        rhs_(t[r], 0) += g.area * (mgx[r] * rot.a + mgy[r] * rot.b);
        rhs_(t[r], 1) += g.area * (mgx[r] * rot.c + mgy[r] * rot.d);
      }
    }
    double meanDiagonal = 0;
    for (int32_t v = 0; v < n_; ++v) meanDiagonal += value[diagonal_[v]];
    meanDiagonal /= std::max(1, n_);
    const double proximal = kProximalRel * (meanDiagonal > 0 ? meanDiagonal : 1);
    for (int32_t v = 0; v < n_; ++v) {
      value[diagonal_[v]] += proximal;
      rhs_(v, 0) += proximal * uv[v].x;
      rhs_(v, 1) += proximal * uv[v].y;
    }
  }

  /// Preconditioned conjugate gradients on both columns from x (each column its own recurrence),
  /// preconditioned by the last factorization. The iterations taken, or −1 without convergence.
  int conjugateGradients(Eigen::MatrixX2d& x) const {
    Eigen::MatrixX2d r = rhs_ - matrix_ * x;
    const Eigen::Array2d floor = 1e-14 * rhs_.colwise().norm().array().transpose();
    const Eigen::Array2d target = (kSolveReduction * r.colwise().norm().array().transpose()).max(floor);
    Eigen::MatrixX2d z = factor_.solve(r);
    Eigen::MatrixX2d p = z;
    Eigen::Array2d rz = (r.array() * z.array()).colwise().sum().transpose();
    for (int it = 0; it <= kMaxConjugateGradient; ++it) {
      const Eigen::Array2d norms = r.colwise().norm().array().transpose();
      if ((norms <= target).all()) return it;
      if (it == kMaxConjugateGradient || !norms.allFinite()) break;
      const Eigen::MatrixX2d q = matrix_ * p;
      for (int c = 0; c < 2; ++c) {
        if (norms(c) <= target(c)) continue;  // this column has converged: leave it
        const double alpha = rz(c) / p.col(c).dot(q.col(c));
        x.col(c) += alpha * p.col(c);
        r.col(c) -= alpha * q.col(c);
      }
      z = factor_.solve(r);
      for (int c = 0; c < 2; ++c) {
        if (norms(c) <= target(c)) continue;
        const double rzNext = r.col(c).dot(z.col(c));
        p.col(c) = z.col(c) + (rzNext / rz(c)) * p.col(c);
        rz(c) = rzNext;
      }
    }
    return -1;
  }

  const TriMesh& mesh_;
  int32_t n_;
  Eigen::SparseMatrix<double> matrix_;
  Eigen::MatrixX2d rhs_;
  std::vector<int32_t> slots_, diagonal_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  bool factored_ = false;  // factor_ holds a usable (possibly older) factorization
};

/// SLIM's local step for one face: the closest rotation to J and the symmetric Dirichlet weight
/// M = V diag(w(σ₁), w(σ₂)) Vᵀ, w(σ) = (σ + 1)(σ² + 1)/σ³ (SLIM's f'(σ)/(2(σ − 1)) for f = σ² + σ⁻²,
/// with the division done by hand), in the face's frame (J = U Σ Vᵀ).
void localStep(const Mat2& j, Mat2& weight, Mat2& rotation) {
  // J = Rot(φ) diag(σ₁, σ₂) Rot(θ) with E, F, G, H below; Rot(φ + θ) is the closest rotation.
  const double e = 0.5 * (j.a + j.d), f = 0.5 * (j.a - j.d), g = 0.5 * (j.c + j.b), h = 0.5 * (j.c - j.b);
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  const double s1 = q + r, s2 = q - r;
  rotation = {e / q, -h / q, h / q, e / q};
  auto w = [](double s) { return (s + 1) * (s * s + 1) / (s * s * s); };
  const double w1 = w(s1), w2 = w(s2);
  // V diag(w₁, w₂) Vᵀ = (w₁ + w₂)/2 I + (w₁ − w₂)/2 V diag(1, −1) Vᵀ, a reflection by the angle 2θ.
  const double mean = 0.5 * (w1 + w2), half = 0.5 * (w1 - w2);
  double cos2 = 1, sin2 = 0;
  if (r > 0) {
    cos2 = (e * f + h * g) / (q * r);
    sin2 = (h * f - e * g) / (q * r);
  }
  weight = {mean + half * cos2, -half * sin2, -half * sin2, mean - half * cos2};
}

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
  const std::vector<FaceGradient> gradients = faceGradients(mesh, false);
  Progress slimProgress = progress;
  if (hasBadFace(mesh, uv) || !std::isfinite(energyOf(mesh, gradients, uv))) {
    // Untangle with the boundary held where the start put it (a convex polygon).
    std::vector<uint8_t> fixed(mesh.numVertices(), 0);
    for (int32_t v = 0; v < mesh.numVertices(); ++v) fixed[v] = mesh.isBoundaryVertex(v) || !referenced[v];
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

  Reporter report(slimProgress);
  GlobalStep global(mesh);
  std::vector<Mat2> weights(mesh.numFaces()), rotations(mesh.numFaces());
  std::vector<Vec2> next, direction(uv.size()), trial(uv.size());
  for (; result.iterations < options.maxIterations; ++result.iterations) {
    if (!report(double(result.iterations) / std::max(1, options.maxIterations)))
      return cancelledError("parameterization");
    if (Clock::now() > deadline) break;
    for (int32_t f = 0; f < mesh.numFaces(); ++f)
      if (gradients[f].area > 0) localStep(jacobian(gradients[f], mesh.triangle(f), uv), weights[f], rotations[f]);
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
