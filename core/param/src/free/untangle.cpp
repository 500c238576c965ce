// untangle.cpp — folded maps made injective: the regularized barrier (Garanzha et al.) minimized by L-BFGS.
#include "untangle.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "symmetric_dirichlet.hpp"

namespace straightest {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kAreaWeight = 1.0 / 128;  // θ: enough to keep faces from shrinking away, small enough to
                                           // leave the shape term (conformal distortion) in charge
constexpr int kMaxRounds = 60;             // values of ε
constexpr int kMaxInner = 200;             // L-BFGS iterations per ε
constexpr int kHistory = 8;                // L-BFGS memory

/// χ(D, ε) = (D + √(ε² + D²)) / 2, written without cancellation for D < 0.
double chi(double d, double eps) {
  const double r = std::sqrt(eps * eps + d * d);
  return d >= 0 ? 0.5 * (d + r) : 0.5 * eps * eps / (r - d);
}

class Barrier {
 public:
  Barrier(const TriMesh& mesh, const std::vector<uint8_t>& fixed, double scale)
      : mesh_(mesh), fixed_(fixed), gradients_(faceGradients(mesh, true)), scale_(scale) {
    for (const FaceGradient& g : gradients_) totalArea_ += g.area;
  }
  double eps = 1;

  /// J relative to the face's scaled 3D shape.
  Mat2 normalizedJacobian(int32_t f, const std::vector<Vec2>& uv) const {
    Mat2 j = jacobian(gradients_[f], mesh_.triangle(f), uv);
    return {j.a * scale_, j.b * scale_, j.c * scale_, j.d * scale_};
  }

  double minDet(const std::vector<Vec2>& uv) const {
    double m = std::numeric_limits<double>::infinity();
    for (int32_t f = 0; f < mesh_.numFaces(); ++f) m = std::min(m, normalizedJacobian(f, uv).det());
    return m;
  }

  /// The energy per unit area; with `gradient` (2 per vertex, zero at fixed vertices) its derivative.
  double evaluate(const std::vector<Vec2>& uv, std::vector<Vec2>* gradient) const {
    if (gradient) gradient->assign(uv.size(), Vec2{});
    double sum = 0;
    for (int32_t f = 0; f < mesh_.numFaces(); ++f) {
      const FaceGradient& g = gradients_[f];
      const Mat2 j = normalizedJacobian(f, uv);
      const double d = j.det(), s = j.squaredNorm(), r = std::sqrt(eps * eps + d * d);
      const double c = chi(d, eps), dc = c / r;  // χ' = χ / √(ε² + D²)
      sum += g.area * ((1 - kAreaWeight) * s + kAreaWeight * (d * d + 1)) / c;
      if (!gradient) continue;
      // ∂f/∂J = (1 − θ) 2J/χ + [−(1 − θ) s χ'/χ² + θ (2D/χ − (D² + 1) χ'/χ²)] cof J.
      const double k = (1 - kAreaWeight) * 2 / c;
      const double m = -(1 - kAreaWeight) * s * dc / (c * c) + kAreaWeight * (2 * d / c - (d * d + 1) * dc / (c * c));
      const Mat2 p{k * j.a + m * j.d, k * j.b - m * j.c, k * j.c - m * j.b, k * j.d + m * j.a};
      const double w = g.area * scale_;
      const Triangle& t = mesh_.triangle(f);
      for (int q = 0; q < 3; ++q) {
        if (fixed_[t[q]]) continue;
        (*gradient)[t[q]] += Vec2{p.a * g.gx[q] + p.b * g.gy[q], p.c * g.gx[q] + p.d * g.gy[q]} * w;
      }
    }
    if (gradient)
      for (Vec2& v : *gradient) v = v / totalArea_;
    return sum / totalArea_;
  }

 private:
  const TriMesh& mesh_;
  const std::vector<uint8_t>& fixed_;
  std::vector<FaceGradient> gradients_;
  double scale_, totalArea_ = 0;
};

double dotAll(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += dot(a[i], b[i]);
  return s;
}

/// L-BFGS's initial inverse Hessian: the inverse of the Dirichlet energy's stiffness on the 3D shape (the
/// cotan Laplacian, fixed vertices held). With the identity instead, a fold along a thin protrusion
/// unwinds about one ring per iteration; the Laplacian spreads each step along the whole surface.
class Preconditioner {
 public:
  Preconditioner(const TriMesh& mesh, const std::vector<uint8_t>& fixed) : fixed_(fixed) {
    const std::vector<FaceGradient> gradients = faceGradients(mesh, true);
    const int32_t n = mesh.numVertices();
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> diagonal(n, 0);
    for (int32_t f = 0; f < mesh.numFaces(); ++f) {
      const FaceGradient& g = gradients[f];
      const Triangle& t = mesh.triangle(f);
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          if (fixed[t[a]] || fixed[t[b]]) continue;
          const double k = g.area * (g.gx[a] * g.gx[b] + g.gy[a] * g.gy[b]);
          if (a == b) diagonal[t[a]] += k;
          else entries.emplace_back(t[a], t[b], k);
        }
    }
    double trace = 0;
    int32_t moving = 0;
    for (int32_t v = 0; v < n; ++v)
      if (!fixed[v]) trace += diagonal[v], ++moving;
    // A small mass term: with no vertex held the Laplacian is singular (translations).
    const double shift = 1e-6 * trace / std::max(1, moving);
    for (int32_t v = 0; v < n; ++v) entries.emplace_back(v, v, fixed[v] ? 1.0 : diagonal[v] + shift);
    Eigen::SparseMatrix<double> k(n, n);
    k.setFromTriplets(entries.begin(), entries.end());
    factor_.compute(k);
    ok_ = factor_.info() == Eigen::Success && moving > 0;
  }

  /// v ← K⁻¹ v (both coordinates; zero at fixed vertices); unchanged if the factorization failed.
  void apply(std::vector<Vec2>& v) const {
    if (!ok_) return;
    const Eigen::Index n = static_cast<Eigen::Index>(v.size());
    Eigen::VectorXd x(n), y(n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = v[i].x, y[i] = v[i].y;
    x = factor_.solve(x);
    y = factor_.solve(y);
    for (Eigen::Index i = 0; i < n; ++i) v[i] = fixed_[i] ? Vec2{} : Vec2{x[i], y[i]};
  }

 private:
  const std::vector<uint8_t>& fixed_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
  bool ok_ = false;
};

/// L-BFGS on the barrier at its current ε, from uv; returns the iterations taken (−1 when cancelled).
int minimize(const Barrier& barrier, const Preconditioner& preconditioner, std::vector<Vec2>& uv,
             Clock::time_point deadline, const std::function<bool(double)>& keepGoing) {
  std::vector<Vec2> scratch;
  std::vector<Vec2> g, gNext, direction(uv.size()), trial(uv.size());
  double e = barrier.evaluate(uv, &g);
  struct Pair {
    std::vector<Vec2> s, y;
    double rho;
  };
  std::deque<Pair> history;
  int it = 0;
  for (; it < kMaxInner; ++it) {
    if (!keepGoing(double(it) / kMaxInner)) return -1;
    if (Clock::now() > deadline) break;
    // Two-loop recursion: direction = −H g.
    for (size_t i = 0; i < uv.size(); ++i) direction[i] = -g[i];
    std::vector<double> alpha(history.size());
    for (size_t k = history.size(); k-- > 0;) {
      alpha[k] = history[k].rho * dotAll(history[k].s, direction);
      for (size_t i = 0; i < uv.size(); ++i) direction[i] -= history[k].y[i] * alpha[k];
    }
    preconditioner.apply(direction);
    if (!history.empty()) {
      const Pair& last = history.back();
      scratch = last.y;
      preconditioner.apply(scratch);
      const double gamma = dotAll(last.s, last.y) / dotAll(last.y, scratch);
      for (Vec2& d : direction) d *= gamma;
    } else {
      double dmax = 0;
      for (const Vec2& v : direction) dmax = std::max({dmax, std::abs(v.x), std::abs(v.y)});
      if (!(dmax > 0) || !std::isfinite(dmax)) break;
      const double first = 1e-3 / dmax;  // a first step that moves no vertex by more than 1e-3
      for (Vec2& d : direction) d *= first;
    }
    for (size_t k = 0; k < history.size(); ++k) {
      const double beta = history[k].rho * dotAll(history[k].y, direction);
      for (size_t i = 0; i < uv.size(); ++i) direction[i] += history[k].s[i] * (alpha[k] - beta);
    }
    double slope = dotAll(g, direction);
    if (!(slope < 0)) {  // not a descent direction: restart from the gradient
      history.clear();
      continue;
    }
    double t = 1, eNext = e;
    bool accepted = false;
    for (int halving = 0; halving < 40; ++halving, t *= 0.5) {
      for (size_t i = 0; i < uv.size(); ++i) trial[i] = uv[i] + direction[i] * t;
      eNext = barrier.evaluate(trial, nullptr);
      if (std::isfinite(eNext) && eNext <= e + 1e-4 * t * slope) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      if (history.empty()) break;
      history.clear();
      continue;
    }
    barrier.evaluate(trial, &gNext);
    Pair p{std::vector<Vec2>(uv.size()), std::vector<Vec2>(uv.size()), 0};
    for (size_t i = 0; i < uv.size(); ++i) {
      p.s[i] = trial[i] - uv[i];
      p.y[i] = gNext[i] - g[i];
    }
    const double sy = dotAll(p.s, p.y);
    if (sy > 1e-300) {
      p.rho = 1 / sy;
      history.push_back(std::move(p));
      if (static_cast<int>(history.size()) > kHistory) history.pop_front();
    }
    const double decrease = e - eNext;
    uv.swap(trial);
    g.swap(gNext);
    e = eNext;
    if (decrease <= 1e-12 * std::abs(e)) break;
  }
  return it;
}

}  // namespace

bool allFacesPositive(const TriMesh& mesh, const std::vector<Vec2>& uv, double margin) {
  double mean = 0;
  for (const Triangle& t : mesh.triangles()) mean += std::abs(twiceSignedArea(t, uv));
  mean /= std::max(1, mesh.numFaces());
  if (!std::isfinite(mean)) return false;
  for (const Triangle& t : mesh.triangles())
    if (!(twiceSignedArea(t, uv) > margin * mean)) return false;
  return true;
}

Expected<UntangleResult> untangle(const TriMesh& mesh, std::vector<Vec2> uv, const std::vector<uint8_t>& fixed,
                                  Clock::time_point deadline, const Progress& progress) {
  UntangleResult result;
  // Scale the faces' 3D shapes to the map's area: the signed area sum is the fixed polygon's.
  double mapArea = 0, surfaceArea = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    mapArea += 0.5 * twiceSignedArea(mesh.triangle(f), uv);
    surfaceArea += mesh.faceArea(f);
  }
  if (!(mapArea > 0) || !(surfaceArea > 0)) {
    result.uv = std::move(uv);
    return result;  // nothing to aim for: a boundary enclosing no area (the caller reports it)
  }
  Barrier barrier(mesh, fixed, std::sqrt(surfaceArea / mapArea));
  const Preconditioner preconditioner(mesh, fixed);
  ThrottledProgress report(progress, "refine");
  double dMin = barrier.minDet(uv);
  barrier.eps = dMin > 0 ? 1e-3 : std::max(1e-3, std::sqrt(1e-12 + 0.04 * dMin * dMin));
  double ePrev = barrier.evaluate(uv, nullptr);
  for (int round = 0; round < kMaxRounds; ++round) {
    // Fraction 1 − 0.8^(rounds done): most starts are untangled within a few rounds, and the fraction
    // keeps moving (so the progress, and its cancellation, is called) however many there are.
    const int inner = minimize(barrier, preconditioner, uv, deadline,
                               [&](double f) { return report(1 - std::pow(0.8, round + f)); });
    if (inner < 0) return cancelledError("parameterization");
    result.iterations += inner;
    dMin = barrier.minDet(uv);
    const double e = barrier.evaluate(uv, nullptr);
    result.injective = allFacesPositive(mesh, uv, kUntangledArea);
    if (result.injective) break;  // SLIM takes it from here: it needs positive faces, not good ones
    if (Clock::now() > deadline) break;
    // Lower ε (Garanzha et al.): the barrier's knee just below the smallest D, by how much this round gained.
    const double sigma = std::max(1 - e / ePrev, 0.1);
    const double mu = (1 - sigma) * chi(dMin, barrier.eps);
    barrier.eps = dMin < mu ? std::max(2 * std::sqrt(mu * (mu - dMin)), 1e-12) : 1e-12;
    ePrev = barrier.evaluate(uv, nullptr);
  }
  result.uv = std::move(uv);
  return result;
}

}  // namespace straightest
