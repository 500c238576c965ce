#include "straightest/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace straightest {

// ------------------------------------------------------------------------------------------------ CSR

void CsrMatrix::multiply2(const double* x, double* y) const {
  for (int32_t r = 0; r < rows; ++r) {
    double s0 = 0, s1 = 0;
    for (int32_t k = start[r]; k < start[r + 1]; ++k) {
      const double a = value[k];
      const int32_t j = col[k];
      s0 += a * x[2 * j];
      s1 += a * x[2 * j + 1];
    }
    y[2 * r] = s0;
    y[2 * r + 1] = s1;
  }
}

Eigen::SparseMatrix<double> CsrMatrix::toEigen() const {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(col.size());
  for (int32_t r = 0; r < rows; ++r)
    for (int32_t k = start[r]; k < start[r + 1]; ++k) t.emplace_back(r, col[k], value[k]);
  Eigen::SparseMatrix<double> m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());  // sums repeated entries, as CsrMatrix means them
  return m;
}

namespace {

/// Gathers one sparse row at a time: a dense slot per column (−1 = empty) and the list of used columns,
/// so a row of any length costs only its own entries (Gustavson's sparse accumulator). Fixed-size
/// buffers and no push_back in add(): a possible reallocation call per entry kept the compilers (and
/// WebAssembly in particular, 4× slower than native) from holding the pointers in registers.
class RowAccumulator {
 public:
  explicit RowAccumulator(int32_t cols) : slot_(cols, -1), cols_(cols), values_(cols) {}
  void add(int32_t c, double v) {
    const int32_t s = slot_[c];
    if (s < 0) {
      slot_[c] = used_;
      cols_[used_] = c;
      values_[used_++] = v;
    } else {
      values_[s] += v;
    }
  }
  /// Appends the row to m (dropping exact zeros when asked) and clears the accumulator.
  void flushInto(CsrMatrix& m, bool dropZeros) {
    size_t at = m.col.size();
    m.col.resize(at + used_);
    m.value.resize(at + used_);
    for (int32_t k = 0; k < used_; ++k) {
      slot_[cols_[k]] = -1;
      if (dropZeros && values_[k] == 0) continue;
      m.col[at] = cols_[k];
      m.value[at++] = values_[k];
    }
    m.col.resize(at);
    m.value.resize(at);
    used_ = 0;
    m.start.push_back(static_cast<int32_t>(at));
  }

 private:
  std::vector<int32_t> slot_, cols_;
  std::vector<double> values_;
  int32_t used_ = 0;
};

CsrMatrix transpose(const CsrMatrix& m) {
  CsrMatrix t;
  t.rows = m.cols;
  t.cols = m.rows;
  t.start.assign(static_cast<size_t>(t.rows) + 1, 0);
  for (int32_t c : m.col) ++t.start[c + 1];
  for (int32_t r = 0; r < t.rows; ++r) t.start[r + 1] += t.start[r];
  t.col.resize(m.col.size());
  t.value.resize(m.value.size());
  std::vector<int32_t> next(t.start.begin(), t.start.end() - 1);
  for (int32_t r = 0; r < m.rows; ++r)
    for (int32_t k = m.start[r]; k < m.start[r + 1]; ++k) {
      const int32_t at = next[m.col[k]]++;
      t.col[at] = r;
      t.value[at] = m.value[k];
    }
  return t;
}

/// a · b by rows (Gustavson).
CsrMatrix multiply(const CsrMatrix& a, const CsrMatrix& b, size_t expectedNonZeros) {
  CsrMatrix c;
  c.rows = a.rows;
  c.cols = b.cols;
  c.start.reserve(static_cast<size_t>(a.rows) + 1);
  c.col.reserve(expectedNonZeros);
  c.value.reserve(expectedNonZeros);
  RowAccumulator acc(b.cols);
  for (int32_t r = 0; r < a.rows; ++r) {
    for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) {
      const int32_t j = a.col[k];
      const double v = a.value[k];
      for (int32_t kk = b.start[j]; kk < b.start[j + 1]; ++kk) acc.add(b.col[kk], v * b.value[kk]);
    }
    acc.flushInto(c, false);
  }
  return c;
}

/// Sorts every row's entries by column (insertion sort: rows are short) and returns, per row, where its
/// entries with column ≥ row begin.
std::vector<int32_t> sortRows(CsrMatrix& m) {
  std::vector<int32_t> split(m.rows);
  for (int32_t r = 0; r < m.rows; ++r) {
    const int32_t b = m.start[r], e = m.start[r + 1];
    for (int32_t k = b + 1; k < e; ++k) {
      const int32_t c = m.col[k];
      const double v = m.value[k];
      int32_t q = k;
      for (; q > b && m.col[q - 1] > c; --q) {
        m.col[q] = m.col[q - 1];
        m.value[q] = m.value[q - 1];
      }
      m.col[q] = c;
      m.value[q] = v;
    }
    int32_t k = b;
    while (k < e && m.col[k] < r) ++k;
    split[r] = k;
  }
  return split;
}

/// Greedy aggregation on the strong-connection graph; returns the aggregate of every node.
std::vector<int32_t> aggregate(const CsrMatrix& A, const std::vector<double>& diag, int32_t& count) {
  const int32_t n = A.rows;
  std::vector<double> root(n);  // sqrt|a_ii|: strong ⇔ |a_ij| ≥ kStrength·root_i·root_j
  for (int32_t i = 0; i < n; ++i) root[i] = std::sqrt(std::abs(diag[i]));
  auto strong = [&](int32_t i, int32_t k) {
    const int32_t j = A.col[k];
    return j != i && std::abs(A.value[k]) >= AggregationMultigrid::kStrength * root[i] * root[j];
  };
  std::vector<int32_t> agg(n, -1);
  count = 0;
  // Pass 1: roots whose strong neighbours are all free take them all.
  for (int32_t i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    bool free = true;
    for (int32_t k = A.start[i]; k < A.start[i + 1] && free; ++k)
      if (agg[A.col[k]] >= 0 && strong(i, k)) free = false;
    if (!free) continue;
    agg[i] = count;
    for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k)
      if (strong(i, k)) agg[A.col[k]] = count;
    ++count;
  }
  // Pass 2: the rest join the aggregate of their strongest aggregated neighbour (as aggregated after
  // pass 1, so the result does not depend on the order within this pass).
  std::vector<int32_t> joined(agg);
  for (int32_t i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    double best = 0;
    for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k)
      if (agg[A.col[k]] >= 0 && strong(i, k) && std::abs(A.value[k]) > best) {
        best = std::abs(A.value[k]);
        joined[i] = agg[A.col[k]];
      }
  }
  agg.swap(joined);
  // Pass 3: isolated leftovers become aggregates of their own.
  for (int32_t i = 0; i < n; ++i)
    if (agg[i] < 0) agg[i] = count++;
  return agg;
}

/// Smoothed prolongator P = (I − ω D⁻¹ A) P0, P0 the aggregates' indicator columns; row i of P is
/// e_agg(i) − (ω / a_ii) Σ_j a_ij e_agg(j).
CsrMatrix smoothedProlongator(const CsrMatrix& A, const std::vector<double>& invDiag, const std::vector<int32_t>& agg,
                              int32_t count) {
  constexpr double omega = 2.0 / 3.0;
  CsrMatrix P;
  P.rows = A.rows;
  P.cols = count;
  P.start.reserve(static_cast<size_t>(A.rows) + 1);
  P.col.reserve(A.col.size() / 2);
  P.value.reserve(A.col.size() / 2);
  RowAccumulator acc(count);
  for (int32_t i = 0; i < A.rows; ++i) {
    acc.add(agg[i], 1.0);
    const double scale = -omega * invDiag[i];
    for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k) acc.add(agg[A.col[k]], scale * A.value[k]);
    acc.flushInto(P, true);
  }
  return P;
}

}  // namespace

// ------------------------------------------------------------------------------------------------ setup

std::vector<int32_t> AggregationMultigrid::sizes() const {
  std::vector<int32_t> s;
  for (const Level& l : levels_) s.push_back(l.A.rows);
  return s;
}

bool AggregationMultigrid::compute(CsrMatrix A, const std::function<bool(double)>& progress) {
  levels_.clear();
  coarse_.reset();
  ok_ = false;
  const double fineRows = std::max(1, A.rows);
  while (true) {
    levels_.emplace_back();
    Level& level = levels_.back();
    level.A = std::move(A);
    level.split = sortRows(level.A);
    const int32_t n = level.A.rows;
    std::vector<double> diag(n, 0.0);
    for (int32_t i = 0; i < n; ++i)
      for (int32_t k = level.A.start[i]; k < level.A.start[i + 1]; ++k)
        if (level.A.col[k] == i) diag[i] += level.A.value[k];
    level.invDiag.resize(n);
    for (int32_t i = 0; i < n; ++i) {
      if (diag[i] == 0 || !std::isfinite(diag[i])) return false;
      level.invDiag[i] = 1.0 / diag[i];
    }
    if (levels_.size() > 1) {
      level.b.resize(2 * static_cast<size_t>(n));
      level.x.resize(2 * static_cast<size_t>(n));
    }
    if (options_.smoother == Smoother::Jacobi) level.tmp.resize(2 * static_cast<size_t>(n));
    if (n <= kCoarseSize || levels_.size() >= 25) break;
    int32_t count = 0;
    const std::vector<int32_t> agg = aggregate(level.A, diag, count);
    if (count >= n || count == 0) break;  // no coarsening possible: stop here
    level.P = smoothedProlongator(level.A, level.invDiag, agg, count);
    // Galerkin coarse operator Pᵀ (A P), both products by rows.
    const CsrMatrix AP = multiply(level.A, level.P, level.P.col.size() * 3);
    A = multiply(transpose(level.P), AP, static_cast<size_t>(count) * 16);
    if (progress && !progress(1.0 - 0.9 * A.rows / fineRows)) return false;
  }
  coarse_ = std::make_shared<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  coarse_->compute(levels_.back().A.toEigen());
  if (coarse_->info() != Eigen::Success) return false;
  coarseRhs_.resize(levels_.back().A.rows, 2);
  ok_ = true;
  return !progress || progress(1.0);
}

// ------------------------------------------------------------------------------------------------ cycle

namespace {

/// One Gauss–Seidel sweep for two interleaved columns, rows first to last (forward) or last to first:
/// x_i += (b_i − (A x)_i) / a_ii with the newest x. Equal to the textbook x_i = (b_i − Σ_{j≠i} a_ij x_j)
/// / a_ii, without a test for the diagonal in the inner loop. The sweep is bound by its loop-carried
/// dependency (x_i needs the x_j just written), so each row sums its columns below i and those from i on
/// in separate accumulators: the sum that waits for the newest values is short and the other one
/// overlaps with the previous row. fromZero: x = 0 on entry, so only the columns below i count (forward).
void gaussSeidel(const CsrMatrix& A, const std::vector<int32_t>& split, const std::vector<double>& invDiag,
                 const double* b, double* x, bool forward, bool fromZero) {
  const int32_t n = A.rows;
  const int32_t* col = A.col.data();
  const double* value = A.value.data();
  for (int32_t s = 0; s < n; ++s) {
    const int32_t i = forward ? s : n - 1 - s;
    double lo0 = 0, lo1 = 0, hi0 = 0, hi1 = 0;
    for (int32_t k = A.start[i]; k < split[i]; ++k) {
      lo0 += value[k] * x[2 * col[k]];
      lo1 += value[k] * x[2 * col[k] + 1];
    }
    if (!fromZero)
      for (int32_t k = split[i]; k < A.start[i + 1]; ++k) {
        hi0 += value[k] * x[2 * col[k]];
        hi1 += value[k] * x[2 * col[k] + 1];
      }
    if (fromZero) {
      x[2 * i] = (b[2 * i] - lo0) * invDiag[i];
      x[2 * i + 1] = (b[2 * i + 1] - lo1) * invDiag[i];
    } else {
      x[2 * i] += (b[2 * i] - lo0 - hi0) * invDiag[i];
      x[2 * i + 1] += (b[2 * i + 1] - lo1 - hi1) * invDiag[i];
    }
  }
}

/// One damped Jacobi step x ← x + ω D⁻¹ (b − A x); tmp is work space of x's size.
void jacobi(const CsrMatrix& A, const std::vector<double>& invDiag, const double* b, double* x, double* tmp) {
  constexpr double omega = 2.0 / 3.0;
  A.multiply2(x, tmp);
  for (int32_t i = 0; i < A.rows; ++i) {
    x[2 * i] += omega * invDiag[i] * (b[2 * i] - tmp[2 * i]);
    x[2 * i + 1] += omega * invDiag[i] * (b[2 * i + 1] - tmp[2 * i + 1]);
  }
}

}  // namespace

void AggregationMultigrid::cycle(size_t l, const double* b, double* x) const {
  const Level& level = levels_[l];
  const int32_t n = level.A.rows;
  if (l + 1 == levels_.size()) {
    for (int32_t i = 0; i < n; ++i) {
      coarseRhs_(i, 0) = b[2 * i];
      coarseRhs_(i, 1) = b[2 * i + 1];
    }
    const Eigen::MatrixXd sol = coarse_->solve(coarseRhs_);
    for (int32_t i = 0; i < n; ++i) {
      x[2 * i] = sol(i, 0);
      x[2 * i + 1] = sol(i, 1);
    }
    return;
  }
  const bool gs = options_.smoother == Smoother::GaussSeidel;
  if (!gs || options_.preSweeps == 0) std::fill(x, x + 2 * static_cast<size_t>(n), 0.0);
  auto smooth = [&](bool forward, bool fromZero) {
    if (gs) gaussSeidel(level.A, level.split, level.invDiag, b, x, forward, fromZero);
    else jacobi(level.A, level.invDiag, b, x, level.tmp.data());
  };
  for (int s = 0; s < options_.preSweeps; ++s) smooth(true, s == 0);
  // Residual and restriction in one pass: b_c = Pᵀ (b − A x), scattered through P's rows.
  const Level& coarse = levels_[l + 1];
  double* bc = coarse.b.data();
  std::fill(bc, bc + 2 * static_cast<size_t>(coarse.A.rows), 0.0);
  const CsrMatrix& A = level.A;
  const CsrMatrix& P = level.P;
  for (int32_t i = 0; i < n; ++i) {
    double r0 = b[2 * i], r1 = b[2 * i + 1];
    for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k) {
      const double a = A.value[k];
      const int32_t j = A.col[k];
      r0 -= a * x[2 * j];
      r1 -= a * x[2 * j + 1];
    }
    for (int32_t k = P.start[i]; k < P.start[i + 1]; ++k) {
      const double p = P.value[k];
      const int32_t c = P.col[k];
      bc[2 * c] += p * r0;
      bc[2 * c + 1] += p * r1;
    }
  }
  double* xc = coarse.x.data();
  cycle(l + 1, bc, xc);
  // Coarse correction x += P x_c.
  for (int32_t i = 0; i < n; ++i) {
    double s0 = 0, s1 = 0;
    for (int32_t k = P.start[i]; k < P.start[i + 1]; ++k) {
      const double p = P.value[k];
      const int32_t c = P.col[k];
      s0 += p * xc[2 * c];
      s1 += p * xc[2 * c + 1];
    }
    x[2 * i] += s0;
    x[2 * i + 1] += s1;
  }
  for (int s = 0; s < options_.postSweeps; ++s) smooth(false, false);
}

void AggregationMultigrid::apply(const double* b, double* x) const { cycle(0, b, x); }

// ------------------------------------------------------------------------------------------------ Krylov

KrylovStats solveTwoColumns(const CsrMatrix& A, const AggregationMultigrid& M, const std::vector<double>& b,
                            std::vector<double>& x, double tolerance, int maxIterations,
                            const std::function<bool(int, double)>& onIteration) {
  KrylovStats stats;
  const size_t n = static_cast<size_t>(A.rows);
  const size_t m = 2 * n;
  // Loops over the interleaved vectors go two entries at a time with one scalar accumulator per
  // column: an accumulator array indexed by i & 1 lived in memory, which WebAssembly paid dearly for.
  double bNorm2[2] = {0, 0};
  for (size_t i = 0; i < m; i += 2) {
    bNorm2[0] += b[i] * b[i];
    bNorm2[1] += b[i + 1] * b[i + 1];
  }
  for (int c = 0; c < 2; ++c)
    if (bNorm2[c] == 0)
      for (size_t i = c; i < m; i += 2) x[i] = 0;  // the exact solution
  std::vector<double> r(m), r0(m), p(m, 0.0), v(m, 0.0), y(m), z(m), s(m), t(m);
  A.multiply2(x.data(), t.data());
  double rNorm2[2] = {0, 0};
  for (size_t i = 0; i < m; ++i) r[i] = r0[i] = b[i] - t[i];
  for (size_t i = 0; i < m; i += 2) {
    rNorm2[0] += r[i] * r[i];
    rNorm2[1] += r[i + 1] * r[i + 1];
  }
  double r0Norm2[2] = {rNorm2[0], rNorm2[1]};
  double rho[2] = {1, 1}, alpha[2] = {1, 1}, omega[2] = {1, 1};
  bool active[2];
  // Σ u_i w_i per column.
  auto dot2 = [m](const std::vector<double>& u, const std::vector<double>& w, double out[2]) {
    double d0 = 0, d1 = 0;
    for (size_t i = 0; i < m; i += 2) {
      d0 += u[i] * w[i];
      d1 += u[i + 1] * w[i + 1];
    }
    out[0] = d0;
    out[1] = d1;
  };
  auto relative = [&](int c) { return bNorm2[c] > 0 ? std::sqrt(rNorm2[c] / bNorm2[c]) : 0.0; };
  auto update = [&]() {
    for (int c = 0; c < 2; ++c) {
      stats.relativeResidual[c] = relative(c);
      active[c] = stats.relativeResidual[c] > tolerance;
    }
  };
  update();
  constexpr double eps2 = std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
  while (active[0] || active[1]) {
    if (stats.iterations >= maxIterations) return stats;
    ++stats.iterations;
    // A column that has converged keeps x and r: its α, ω and β are 0, so x += 0, s = r, r = s and
    // p = r (finite, unlike whatever its stale recurrences would give).
    double beta[2], rhoOld[2] = {rho[0], rho[1]};
    double dot[2];
    dot2(r0, r, dot);
    for (int c = 0; c < 2; ++c) {
      rho[c] = dot[c];
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
    for (size_t i = 0; i < m; i += 2) {
      p[i] = r[i] + b0 * (p[i] - w0 * v[i]);
      p[i + 1] = r[i + 1] + b1 * (p[i + 1] - w1 * v[i + 1]);
    }
    M.apply(p.data(), y.data());
    A.multiply2(y.data(), v.data());
    dot2(r0, v, dot);
    for (int c = 0; c < 2; ++c) alpha[c] = active[c] ? rho[c] / dot[c] : 0.0;
    double sNorm2[2];
    {
      const double al0 = alpha[0], al1 = alpha[1];
      double n0 = 0, n1 = 0;
      for (size_t i = 0; i < m; i += 2) {
        s[i] = r[i] - al0 * v[i];
        s[i + 1] = r[i + 1] - al1 * v[i + 1];
        n0 += s[i] * s[i];
        n1 += s[i + 1] * s[i + 1];
      }
      sNorm2[0] = n0;
      sNorm2[1] = n1;
    }
    // Half-step exit: a column whose s is already small enough takes x += α y and stops here, which
    // often saves the last iteration's second V-cycle.
    for (int c = 0; c < 2; ++c) {
      if (!active[c] || !std::isfinite(alpha[c]) || sNorm2[c] > tolerance * tolerance * bNorm2[c]) continue;
      for (size_t i = c; i < m; i += 2) {
        x[i] += alpha[c] * y[i];
        r[i] = s[i];
      }
      rNorm2[c] = sNorm2[c];
      stats.relativeResidual[c] = relative(c);
      active[c] = false;
      alpha[c] = omega[c] = 1;  // finite values for the skipped recurrences, as below
    }
    if (!active[0] && !active[1]) {
      if (onIteration) onIteration(stats.iterations, std::max(stats.relativeResidual[0], stats.relativeResidual[1]));
      break;  // done: a cancellation now would gain nothing
    }
    M.apply(s.data(), z.data());
    A.multiply2(z.data(), t.data());
    double tt[2], ts[2];
    dot2(t, t, tt);
    dot2(t, s, ts);
    for (int c = 0; c < 2; ++c)
      if (active[c]) omega[c] = tt[c] > 0 ? ts[c] / tt[c] : 0.0;
    // Inactive columns (converged before or at the half step) get coefficients 0: x and r stay.
    const double a0 = active[0] ? alpha[0] : 0.0, a1 = active[1] ? alpha[1] : 0.0;
    const double o0 = active[0] ? omega[0] : 0.0, o1 = active[1] ? omega[1] : 0.0;
    double n0 = 0, n1 = 0;
    for (size_t i = 0; i < m; i += 2) {
      x[i] += a0 * y[i] + o0 * z[i];
      x[i + 1] += a1 * y[i + 1] + o1 * z[i + 1];
      r[i] = s[i] - o0 * t[i];
      r[i + 1] = s[i + 1] - o1 * t[i + 1];
      n0 += r[i] * r[i];
      n1 += r[i + 1] * r[i + 1];
    }
    rNorm2[0] = n0;
    rNorm2[1] = n1;
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
    if (onIteration && !onIteration(stats.iterations, std::max(stats.relativeResidual[0], stats.relativeResidual[1]))) {
      stats.cancelled = true;
      return stats;
    }
  }
  stats.converged = true;
  return stats;
}

}  // namespace straightest
