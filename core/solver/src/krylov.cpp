// krylov.cpp — the two-column lockstep BiCGSTAB. Its vector updates run on all threads in fixed row
// chunks, and its dot products and norms add per-chunk sums in chunk order (row_chunks.hpp): the
// iterates are bit-identical for any thread count.
#include "straightest/solver/krylov.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "row_chunks.hpp"
#include "row_product.hpp"
#include "solve_progress.hpp"

namespace straightest {
namespace {

/// y = A x for the two interleaved columns, and N sums that add(i, sums) accumulates from each row just
/// after it is computed (i = 2·row): one pass over the rows instead of a product and then a reduction,
/// with the same row kernel as CsrMatrix::multiply2 (row_product.hpp) and the same chunks and order of the sums as
/// sumRowChunks — the same bits as the two passes.
template <std::size_t N, class Add>
std::array<double, N> productSums(const CsrMatrix& A, const std::vector<double>& x, std::vector<double>& y,
                                  const Add& add) {
  const detail::CsrRows rows(A);
  const double* xv = x.data();
  double* yv = y.data();
  return detail::sumRowChunks<N>(static_cast<std::size_t>(A.rows),
                                 [&](std::size_t begin, std::size_t end, double* sum) {
                                   for (std::size_t r = begin; r < end; ++r) {
                                     detail::rowTimesTwoColumns(rows, r, xv, yv);
                                     add(2 * r, sum);
                                   }
                                 });
}

// Loops over the interleaved vectors go two entries (one row) at a time with one scalar accumulator
// per column: an accumulator array indexed by i & 1 lived in memory, which WebAssembly paid dearly for.
using detail::forRowChunks;
using detail::sumRowChunks;

/// The lockstep iteration: its vectors, each column's scalars, and one method per phase of a step.
class TwoColumnBicgstab {
 public:
  TwoColumnBicgstab(const CsrMatrix& A, const TwoColumnPreconditioner& M, const std::vector<double>& b,
                    std::vector<double>& x, double tolerance, KrylovStats& stats)
      : A_(A), M_(M), b_(b), x_(x), tolerance_(tolerance), stats_(stats), n_(static_cast<size_t>(A.rows)), m_(2 * n_) {}

  /// |b|² per column (a zero column's solution is exactly 0), then r = r0 = b − A x and its norms.
  void start() {
    const std::vector<double>& b = b_;
    std::vector<double>& x = x_;
    const size_t n = n_, m = m_;
    const double* bv = b.data();
    const auto bSums = sumRowChunks<2>(n, [bv](size_t begin, size_t end, double* sum) {
      double n0 = 0, n1 = 0;
      for (size_t i = 2 * begin; i < 2 * end; i += 2) {
        n0 += bv[i] * bv[i];
        n1 += bv[i + 1] * bv[i + 1];
      }
      sum[0] = n0;
      sum[1] = n1;
    });
    bNorm2_[0] = bSums[0];
    bNorm2_[1] = bSums[1];
    for (int c = 0; c < 2; ++c)
      if (bNorm2_[c] == 0)
        for (size_t i = c; i < m; i += 2) x[i] = 0;  // the exact solution
    // s = r − α v is written over r (r is not needed once s is known, and r = s − ω t is then formed in
    // place): seven vectors instead of eight, 16 bytes per row less memory to touch.
    r_.resize(m), r0_.resize(m), p_.assign(m, 0.0), v_.assign(m, 0.0), y_.resize(m), z_.resize(m), t_.resize(m);
    std::vector<double>&r = r_, &r0 = r0_, &t = t_;
    A_.multiply2(x.data(), t.data());
    const auto rSums = sumRowChunks<2>(n, [&](size_t begin, size_t end, double* sum) {
      double n0 = 0, n1 = 0;
      for (size_t i = 2 * begin; i < 2 * end; i += 2) {
        r[i] = r0[i] = b[i] - t[i];
        r[i + 1] = r0[i + 1] = b[i + 1] - t[i + 1];
        n0 += r[i] * r[i];
        n1 += r[i + 1] * r[i + 1];
      }
      sum[0] = n0;
      sum[1] = n1;
    });
    rNorm2_[0] = rSums[0];
    rNorm2_[1] = rSums[1];
    r0Norm2_[0] = rNorm2_[0];
    r0Norm2_[1] = rNorm2_[1];
    // r0·r for the coming iteration: computed in the pass that writes r (here r = r0, so it is |r|²), not in
    // a pass of its own that would read both vectors again.
    r0DotR_[0] = rNorm2_[0];
    r0DotR_[1] = rNorm2_[1];
    update();
  }

  bool anyActive() const { return active_[0] || active_[1]; }
  double largerResidual() const { return std::max(stats_.relativeResidual[0], stats_.relativeResidual[1]); }

  /// ρ and β per column (a column whose r has become orthogonal to r0 restarts from its true residual),
  /// then p = r + β (p − ω v), y = M p, v = A y and α = ρ / (r0·v).
  void direction() {
    std::vector<double>&r = r_, &r0 = r0_, &p = p_, &v = v_, &y = y_, &t = t_;
    const std::vector<double>& b = b_;
    const size_t n = n_, m = m_;
    constexpr double eps2 = std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
    // A column that has converged keeps x and r: its α, ω and β are 0, so x += 0, s = r, r = s and
    // p = r (finite, unlike whatever its stale recurrences would give).
    double beta[2], rhoOld[2] = {rho_[0], rho_[1]};
    double dot[2];
    for (int c = 0; c < 2; ++c) {
      rho_[c] = r0DotR_[c];
      if (active_[c] && std::abs(rho_[c]) < eps2 * r0Norm2_[c]) {
        // r has become orthogonal to r0: restart this column's recurrence from its true residual.
        A_.multiply2(x_.data(), t.data());
        double norm2 = 0;
        for (size_t i = c; i < m; i += 2) {
          r[i] = r0[i] = b[i] - t[i];
          norm2 += r[i] * r[i];
        }
        rho_[c] = r0Norm2_[c] = norm2;
      }
      beta[c] = active_[c] ? (rho_[c] / rhoOld[c]) * (alpha_[c] / omega_[c]) : 0.0;
    }
    const double w0 = active_[0] ? omega_[0] : 0.0, w1 = active_[1] ? omega_[1] : 0.0;
    const double b0 = beta[0], b1 = beta[1];
    forRowChunks(n, [&](size_t begin, size_t end) {
      for (size_t i = 2 * begin; i < 2 * end; i += 2) {
        p[i] = r[i] + b0 * (p[i] - w0 * v[i]);
        p[i + 1] = r[i + 1] + b1 * (p[i + 1] - w1 * v[i + 1]);
      }
    });
    M_(p.data(), y.data());
    {
      // v = A y and r0·v in one pass over the rows (the same chunks and order as a separate sum).
      const auto sums = productSums<2>(A_, y, v, [&](size_t i, double* sum) {
        sum[0] += r0[i] * v[i];
        sum[1] += r0[i + 1] * v[i + 1];
      });
      dot[0] = sums[0];
      dot[1] = sums[1];
    }
    for (int c = 0; c < 2; ++c) alpha_[c] = active_[c] ? rho_[c] / dot[c] : 0.0;
  }

  /// s = r − α v and |s|²; a column whose s is already small enough takes x += α y and stops here.
  void halfStep() {
    std::vector<double>&s = r_, &v = v_, &y = y_, &x = x_;
    const size_t n = n_, m = m_;
    const double tolerance = tolerance_;
    double sNorm2[2];
    {
      const double al0 = alpha_[0], al1 = alpha_[1];
      const auto sums = sumRowChunks<2>(n, [&](size_t begin, size_t end, double* sum) {
        double n0 = 0, n1 = 0;
        for (size_t i = 2 * begin; i < 2 * end; i += 2) {
          s[i] -= al0 * v[i];
          s[i + 1] -= al1 * v[i + 1];
          n0 += s[i] * s[i];
          n1 += s[i + 1] * s[i + 1];
        }
        sum[0] = n0;
        sum[1] = n1;
      });
      sNorm2[0] = sums[0];
      sNorm2[1] = sums[1];
    }
    // Half-step exit: a column whose s is already small enough takes x += α y and stops here, which
    // often saves the last iteration's second V-cycle.
    for (int c = 0; c < 2; ++c) {
      if (!active_[c] || !std::isfinite(alpha_[c]) || sNorm2[c] > tolerance * tolerance * bNorm2_[c]) continue;
      for (size_t i = c; i < m; i += 2) x[i] += alpha_[c] * y[i];  // r already holds s
      rNorm2_[c] = sNorm2[c];
      stats_.relativeResidual[c] = relative(c);
      active_[c] = false;
      alpha_[c] = omega_[c] = 1;  // finite values for the skipped recurrences, as below
    }
  }

  /// z = M s, t = A z, ω = t·s / t·t, then x += α y + ω z and r = s − ω t with |r|² and r0·r. False
  /// when a column broke down (a non-finite value, or ω = 0 short of the tolerance).
  bool secondHalf() {
    std::vector<double>&s = r_, &r = r_, &r0 = r0_, &y = y_, &z = z_, &t = t_, &x = x_;
    const size_t n = n_;
    const double tolerance = tolerance_;
    M_(s.data(), z.data());
    // t = A z, with t·t and t·s per column, in one pass over the rows.
    const auto tSums = productSums<4>(A_, z, t, [&](size_t i, double* sum) {
      sum[0] += t[i] * t[i];
      sum[1] += t[i + 1] * t[i + 1];
      sum[2] += t[i] * s[i];
      sum[3] += t[i + 1] * s[i + 1];
    });
    const double tt[2] = {tSums[0], tSums[1]}, ts[2] = {tSums[2], tSums[3]};
    for (int c = 0; c < 2; ++c)
      if (active_[c]) omega_[c] = tt[c] > 0 ? ts[c] / tt[c] : 0.0;
    // Inactive columns (converged before or at the half step) get coefficients 0: x and r stay.
    const double a0 = active_[0] ? alpha_[0] : 0.0, a1 = active_[1] ? alpha_[1] : 0.0;
    const double o0 = active_[0] ? omega_[0] : 0.0, o1 = active_[1] ? omega_[1] : 0.0;
    const auto newSums = sumRowChunks<4>(n, [&](size_t begin, size_t end, double* sum) {
      double n0 = 0, n1 = 0, d0 = 0, d1 = 0;
      for (size_t i = 2 * begin; i < 2 * end; i += 2) {
        x[i] += a0 * y[i] + o0 * z[i];
        x[i + 1] += a1 * y[i + 1] + o1 * z[i + 1];
        r[i] -= o0 * t[i];  // r holds s
        r[i + 1] -= o1 * t[i + 1];
        n0 += r[i] * r[i];
        n1 += r[i + 1] * r[i + 1];
        d0 += r0[i] * r[i];
        d1 += r0[i + 1] * r[i + 1];
      }
      sum[0] = n0;
      sum[1] = n1;
      sum[2] = d0;
      sum[3] = d1;
    });
    rNorm2_[0] = newSums[0];
    rNorm2_[1] = newSums[1];
    r0DotR_[0] = newSums[2];
    r0DotR_[1] = newSums[3];
    for (int c = 0; c < 2; ++c) {
      if (!active_[c]) continue;
      if (!std::isfinite(rNorm2_[c]) || !std::isfinite(alpha_[c]) || !std::isfinite(omega_[c])) return false;
      // ω = 0 would make the next β divide by zero: the method has broken down for this column.
      if (omega_[c] == 0 && rNorm2_[c] > tolerance * tolerance * bNorm2_[c]) return false;
    }
    // Keep a converged column's ω and α at values that leave the (skipped) recurrences finite.
    const bool wasActive[2] = {active_[0], active_[1]};
    update();
    for (int c = 0; c < 2; ++c)
      if (wasActive[c] && !active_[c]) alpha_[c] = omega_[c] = 1;
    return true;
  }

 private:
  double relative(int c) const { return bNorm2_[c] > 0 ? std::sqrt(rNorm2_[c] / bNorm2_[c]) : 0.0; }
  void update() {
    for (int c = 0; c < 2; ++c) {
      stats_.relativeResidual[c] = relative(c);
      active_[c] = stats_.relativeResidual[c] > tolerance_;
    }
  }

  const CsrMatrix& A_;
  const TwoColumnPreconditioner& M_;
  const std::vector<double>& b_;
  std::vector<double>& x_;
  const double tolerance_;
  KrylovStats& stats_;
  const size_t n_, m_;
  std::vector<double> r_, r0_, p_, v_, y_, z_, t_;  // s is written over r
  double bNorm2_[2] = {0, 0}, rNorm2_[2] = {0, 0}, r0Norm2_[2] = {0, 0}, r0DotR_[2] = {0, 0};
  double rho_[2] = {1, 1}, alpha_[2] = {1, 1}, omega_[2] = {1, 1};
  bool active_[2] = {false, false};
};

}  // namespace

Expected<KrylovStats> solveTwoColumns(const CsrMatrix& A, const TwoColumnPreconditioner& M,
                                      const std::vector<double>& b, std::vector<double>& x, double tolerance,
                                      int maxIterations, const Progress& progress) {
  KrylovStats stats;
  TwoColumnBicgstab solver(A, M, b, x, tolerance, stats);
  solver.start();
  ResidualProgress reportResidual(progress, solver.largerResidual(), tolerance);
  while (solver.anyActive()) {
    if (stats.iterations >= maxIterations) return stats;
    ++stats.iterations;
    solver.direction();
    solver.halfStep();
    if (!solver.anyActive()) {
      reportResidual(solver.largerResidual());
      break;  // done: a cancellation now would gain nothing
    }
    if (!solver.secondHalf()) return stats;
    if (!reportResidual(solver.largerResidual())) return cancelledError("linear solve");
  }
  stats.converged = true;
  return stats;
}

}  // namespace straightest
