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

}  // namespace

Expected<KrylovStats> solveTwoColumns(const CsrMatrix& A, const TwoColumnPreconditioner& M,
                                      const std::vector<double>& b, std::vector<double>& x, double tolerance,
                                      int maxIterations, const Progress& progress) {
  KrylovStats stats;
  const size_t n = static_cast<size_t>(A.rows);
  const size_t m = 2 * n;
  // Loops over the interleaved vectors go two entries (one row) at a time with one scalar accumulator
  // per column: an accumulator array indexed by i & 1 lived in memory, which WebAssembly paid dearly for.
  using detail::forRowChunks;
  using detail::sumRowChunks;
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
  const double bNorm2[2] = {bSums[0], bSums[1]};
  for (int c = 0; c < 2; ++c)
    if (bNorm2[c] == 0)
      for (size_t i = c; i < m; i += 2) x[i] = 0;  // the exact solution
  // s = r − α v is written over r (r is not needed once s is known, and r = s − ω t is then formed in
  // place): seven vectors instead of eight, 16 bytes per row less memory to touch.
  std::vector<double> r(m), r0(m), p(m, 0.0), v(m, 0.0), y(m), z(m), t(m);
  std::vector<double>& s = r;
  A.multiply2(x.data(), t.data());
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
  double rNorm2[2] = {rSums[0], rSums[1]};
  double r0Norm2[2] = {rNorm2[0], rNorm2[1]};
  // r0·r for the coming iteration: computed in the pass that writes r (here r = r0, so it is |r|²), not in
  // a pass of its own that would read both vectors again.
  double r0DotR[2] = {rNorm2[0], rNorm2[1]};
  double rho[2] = {1, 1}, alpha[2] = {1, 1}, omega[2] = {1, 1};
  bool active[2];
  auto relative = [&](int c) { return bNorm2[c] > 0 ? std::sqrt(rNorm2[c] / bNorm2[c]) : 0.0; };
  auto update = [&]() {
    for (int c = 0; c < 2; ++c) {
      stats.relativeResidual[c] = relative(c);
      active[c] = stats.relativeResidual[c] > tolerance;
    }
  };
  update();
  auto largerResidual = [&]() { return std::max(stats.relativeResidual[0], stats.relativeResidual[1]); };
  ResidualProgress reportResidual(progress, largerResidual(), tolerance);
  constexpr double eps2 = std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
  while (active[0] || active[1]) {
    if (stats.iterations >= maxIterations) return stats;
    ++stats.iterations;
    // A column that has converged keeps x and r: its α, ω and β are 0, so x += 0, s = r, r = s and
    // p = r (finite, unlike whatever its stale recurrences would give).
    double beta[2], rhoOld[2] = {rho[0], rho[1]};
    double dot[2];
    for (int c = 0; c < 2; ++c) {
      rho[c] = r0DotR[c];
      if (active[c] && std::abs(rho[c]) < eps2 * r0Norm2[c]) {
        // r has become orthogonal to r0: restart this column's recurrence from its true residual.
        A.multiply2(x.data(), t.data());
        double norm2 = 0;
        for (size_t i = c; i < m; i += 2) {
          r[i] = r0[i] = b[i] - t[i];
          norm2 += r[i] * r[i];
        }
        rho[c] = r0Norm2[c] = norm2;
      }
      beta[c] = active[c] ? (rho[c] / rhoOld[c]) * (alpha[c] / omega[c]) : 0.0;
    }
    const double w0 = active[0] ? omega[0] : 0.0, w1 = active[1] ? omega[1] : 0.0;
    const double b0 = beta[0], b1 = beta[1];
    forRowChunks(n, [&](size_t begin, size_t end) {
      for (size_t i = 2 * begin; i < 2 * end; i += 2) {
        p[i] = r[i] + b0 * (p[i] - w0 * v[i]);
        p[i + 1] = r[i + 1] + b1 * (p[i + 1] - w1 * v[i + 1]);
      }
    });
    M(p.data(), y.data());
    {
      // v = A y and r0·v in one pass over the rows (the same chunks and order as a separate sum).
      const auto sums = productSums<2>(A, y, v, [&](size_t i, double* sum) {
        sum[0] += r0[i] * v[i];
        sum[1] += r0[i + 1] * v[i + 1];
      });
      dot[0] = sums[0];
      dot[1] = sums[1];
    }
    for (int c = 0; c < 2; ++c) alpha[c] = active[c] ? rho[c] / dot[c] : 0.0;
    double sNorm2[2];
    {
      const double al0 = alpha[0], al1 = alpha[1];
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
      if (!active[c] || !std::isfinite(alpha[c]) || sNorm2[c] > tolerance * tolerance * bNorm2[c]) continue;
      for (size_t i = c; i < m; i += 2) x[i] += alpha[c] * y[i];  // r already holds s
      rNorm2[c] = sNorm2[c];
      stats.relativeResidual[c] = relative(c);
      active[c] = false;
      alpha[c] = omega[c] = 1;  // finite values for the skipped recurrences, as below
    }
    if (!active[0] && !active[1]) {
      reportResidual(largerResidual());
      break;  // done: a cancellation now would gain nothing
    }
    M(s.data(), z.data());
    // t = A z, with t·t and t·s per column, in one pass over the rows.
    const auto tSums = productSums<4>(A, z, t, [&](size_t i, double* sum) {
      sum[0] += t[i] * t[i];
      sum[1] += t[i + 1] * t[i + 1];
      sum[2] += t[i] * s[i];
      sum[3] += t[i + 1] * s[i + 1];
    });
    const double tt[2] = {tSums[0], tSums[1]}, ts[2] = {tSums[2], tSums[3]};
    for (int c = 0; c < 2; ++c)
      if (active[c]) omega[c] = tt[c] > 0 ? ts[c] / tt[c] : 0.0;
    // Inactive columns (converged before or at the half step) get coefficients 0: x and r stay.
    const double a0 = active[0] ? alpha[0] : 0.0, a1 = active[1] ? alpha[1] : 0.0;
    const double o0 = active[0] ? omega[0] : 0.0, o1 = active[1] ? omega[1] : 0.0;
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
    rNorm2[0] = newSums[0];
    rNorm2[1] = newSums[1];
    r0DotR[0] = newSums[2];
    r0DotR[1] = newSums[3];
    for (int c = 0; c < 2; ++c) {
      if (!active[c]) continue;
      if (!std::isfinite(rNorm2[c]) || !std::isfinite(alpha[c]) || !std::isfinite(omega[c])) return stats;
      // ω = 0 would make the next β divide by zero: the method has broken down for this column.
      if (omega[c] == 0 && rNorm2[c] > tolerance * tolerance * bNorm2[c]) return stats;
    }
    // Keep a converged column's ω and α at values that leave the (skipped) recurrences finite.
    const bool wasActive[2] = {active[0], active[1]};
    update();
    for (int c = 0; c < 2; ++c)
      if (wasActive[c] && !active[c]) alpha[c] = omega[c] = 1;
    if (!reportResidual(largerResidual())) return cancelledError("linear solve");
  }
  stats.converged = true;
  return stats;
}

}  // namespace straightest
