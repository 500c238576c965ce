// multigrid.cpp — the smoothed-aggregation hierarchy (aggregation, smoothed prolongator, Galerkin
// coarse operators) and its V-cycle; the coarsest level is factorized by Eigen's SparseLU.
// Threads (row_chunks.hpp): the cycle's residual, restriction (by the rows of R = Pᵀ, kept from the
// setup), prolongation and Jacobi steps run in fixed row chunks on all threads, each row computed as on
// one thread. A Gauss–Seidel sweep needs each row after the rows it reads; its order (SweepOrder) sweeps
// blocks of rows that read nothing outside their block on all threads, then the rows on the blocks'
// borders. So the V-cycle is the same operator — and the results the same bits — however many threads
// run it.
#include "straightest/solver/multigrid.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "row_accumulator.hpp"
#include "row_chunks.hpp"
#include "solve_progress.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/solver/eigen_bridge.hpp"

namespace straightest {

// Not in an anonymous namespace: a level of the (header-declared) hierarchy holds one, and a member of an
// internal-linkage type would make the hierarchy's type differ between translation units (GCC's
// -Wsubobject-linkage, which a unity build turns on for this file).
namespace multigrid_detail {

/// The order of a level's Gauss–Seidel sweeps, fixed at setup from the matrix alone. The rows are cut
/// into blocks (detail::rowPieces: fixed by the row count); a block's inner rows have every column
/// inside the block, its border rows do not. A forward sweep relaxes the blocks' inner rows, block after
/// block, then the border rows in ascending order; a backward sweep the exact reverse. No inner row reads
/// another block, so the blocks run on all threads and the sweep is one and the same Gauss–Seidel sweep
/// — the same bits — on any number of threads. The border rows, swept on one thread, are the few rows
/// next to a cut (a small share on a mesh numbered by neighbourhood; all of them only on a mesh whose
/// neighbours are scattered across the numbering, where the sweep is the plain sequential one).
struct SweepOrder {
  std::vector<int32_t> blockStart;   // every block's first row, then the row count
  std::vector<int32_t> border;       // the border rows, ascending
  std::vector<int32_t> blockBorder;  // every block's first entry in border, then border.size()
};

SweepOrder sweepOrder(const CsrMatrix& A) {
  SweepOrder order;
  order.blockStart = detail::rowPieces(A.rows);
  const size_t blocks = order.blockStart.size() - 1;
  for (size_t k = 0; k < blocks; ++k) {
    order.blockBorder.push_back(static_cast<int32_t>(order.border.size()));
    const int32_t begin = order.blockStart[k], end = order.blockStart[k + 1];
    for (int32_t i = begin; i < end; ++i) {
      if (A.start[i] == A.start[i + 1]) continue;  // rows are sorted: the first and last column bound them
      if (A.col[A.start[i]] < begin || A.col[A.start[i + 1] - 1] >= end) order.border.push_back(i);
    }
  }
  order.blockBorder.push_back(static_cast<int32_t>(order.border.size()));
  return order;
}

}  // namespace multigrid_detail

using multigrid_detail::SweepOrder;
using multigrid_detail::sweepOrder;

struct AggregationMultigrid::Hierarchy {
  struct Level {
    CsrMatrix A;
    CsrMatrix P;                 // prolongator to this level from the next coarser one
    CsrMatrix R;                 // Pᵀ, the restriction: row c sums its fine rows in ascending order
    std::vector<int32_t> split;  // per row: first entry with column ≥ row (rows are sorted)
    SweepOrder order;            // the Gauss–Seidel sweeps' row order
    std::vector<double> invDiag;
    // The cycle's copies of A's, P's and R's values in single precision (P and R keep no others): 8
    // bytes per entry instead of 12 (value and column) are fewer cache lines to wait for in the
    // sweeps' scattered reads. Still a fixed linear operator, as the Krylov
    // solver needs; its own products and residuals stay in double precision (matrix()), so the
    // solution's accuracy is unchanged.
    std::vector<float> a32, p32, r32;
    // Work space, two entries per unknown: b and x of the coarser levels' cycles; tmp holds the
    // residual before restriction (and A x in a Jacobi step).
    mutable std::vector<double> b, x, tmp;
  };
  std::vector<Level> levels;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> coarse;
  mutable Eigen::MatrixXd coarseRhs;
  bool ok = false;

  void cycle(const Options& options, size_t level, const double* b, double* x) const;
};

namespace {

/// The values rounded to single precision, on all threads.
std::vector<float> toSingle(const std::vector<double>& values) {
  std::vector<float> out(values.size());
  detail::forRowChunks(values.size(), [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) out[k] = static_cast<float>(values[k]);
  });
  return out;
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
  return buildRows(A.rows, count, A.col.size() / 2, true, [&](int32_t i, RowAccumulator& acc) {
    acc.add(agg[i], 1.0);
    const double scale = -omega * invDiag[i];
    for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k) acc.add(agg[A.col[k]], scale * A.value[k]);
  });
}

}  // namespace

// ------------------------------------------------------------------------------------------------ setup

AggregationMultigrid::AggregationMultigrid() : AggregationMultigrid(Options{}) {}
AggregationMultigrid::AggregationMultigrid(Options options)
    : options_(options), hierarchy_(std::make_unique<Hierarchy>()) {}
AggregationMultigrid::~AggregationMultigrid() = default;
AggregationMultigrid::AggregationMultigrid(AggregationMultigrid&&) noexcept = default;
AggregationMultigrid& AggregationMultigrid::operator=(AggregationMultigrid&&) noexcept = default;

bool AggregationMultigrid::ok() const { return hierarchy_ && hierarchy_->ok; }
const CsrMatrix& AggregationMultigrid::matrix() const { return hierarchy_->levels.front().A; }
int AggregationMultigrid::levels() const { return hierarchy_ ? static_cast<int>(hierarchy_->levels.size()) : 0; }

std::vector<int32_t> AggregationMultigrid::sizes() const {
  std::vector<int32_t> s;
  if (hierarchy_)
    for (const Hierarchy::Level& l : hierarchy_->levels) s.push_back(l.A.rows);
  return s;
}

Expected<bool> AggregationMultigrid::compute(CsrMatrix A, const Progress& progress) {
  hierarchy_ = std::make_unique<Hierarchy>();
  std::vector<Hierarchy::Level>& levels = hierarchy_->levels;
  const double fineRows = std::max(1, A.rows);
  while (true) {
    levels.emplace_back();
    Hierarchy::Level& level = levels.back();
    level.A = std::move(A);
    level.split = sortRows(level.A);
    level.order = sweepOrder(level.A);
    level.a32 = toSingle(level.A.value);
    const int32_t n = level.A.rows;
    const std::vector<double> diag = diagonal(level.A);
    level.invDiag.resize(n);
    for (int32_t i = 0; i < n; ++i) {
      if (diag[i] == 0 || !std::isfinite(diag[i])) return false;
      level.invDiag[i] = 1.0 / diag[i];
    }
    if (levels.size() > 1) {
      level.b.resize(2 * static_cast<size_t>(n));
      level.x.resize(2 * static_cast<size_t>(n));
    }
    const bool jacobi = options_.smoother == Smoother::Jacobi;
    if (jacobi) level.tmp.resize(2 * static_cast<size_t>(n));
    if (n <= kCoarseSize || levels.size() >= 25) break;
    int32_t count = 0;
    const std::vector<int32_t> agg = aggregate(level.A, diag, count);
    if (count >= n || count == 0) break;                        // no coarsening possible: stop here
    if (!jacobi) level.tmp.resize(2 * static_cast<size_t>(n));  // the residual
    level.P = smoothedProlongator(level.A, level.invDiag, agg, count);
    level.R = transpose(level.P);
    // Galerkin coarse operator Pᵀ (A P), both products by rows. A P is read only by the rows of Pᵀ, so it
    // stays in the pieces it was built in: joining them would copy it whole for nothing.
    const RowPieces AP = multiplyInPieces(level.A, level.P, level.P.col.size() * 3);
    A = multiply(level.R, AP, static_cast<size_t>(count) * 16);
    level.p32 = toSingle(level.P.value);
    level.r32 = toSingle(level.R.value);
    std::vector<double>().swap(level.P.value);
    std::vector<double>().swap(level.R.value);
    if (!progress(kSolveStage, 1.0 - 0.9 * A.rows / fineRows)) return cancelledError("multigrid setup");
  }
  hierarchy_->coarse.compute(toEigen(levels.back().A));
  if (hierarchy_->coarse.info() != Eigen::Success) return false;
  hierarchy_->coarseRhs.resize(levels.back().A.rows, 2);
  if (!progress(kSolveStage, 1.0)) return cancelledError("multigrid setup");
  hierarchy_->ok = true;
  return true;
}

// ------------------------------------------------------------------------------------------------ cycle

namespace {

/// Relaxes row i of both interleaved columns (u and v): x_i += (b_i − (A x)_i) / a_ii with the newest x.
/// Equal to the textbook x_i = (b_i − Σ_{j≠i} a_ij x_j) / a_ii, without a test for the diagonal in the
/// inner loop. A sweep is bound by its loop-carried dependency (x_i needs the x_j just written), so the
/// row sums its columns below i and those from i on in separate accumulators: the sum that waits for the
/// newest values is short and the other one overlaps with the previous row. FromZero: every x_j the sweep
/// has not yet written is 0, so only the columns below i count (a forward sweep from x = 0).
template <bool FromZero>
inline void relaxRow(const CsrMatrix& A, const float* value, const int32_t* split, const double* invDiag,
                     const double* b, double* x, int32_t i) {
  const int32_t* col = A.col.data();
  double lo0 = 0, lo1 = 0, hi0 = 0, hi1 = 0;
  for (int32_t k = A.start[i]; k < split[i]; ++k) {
    const double a = value[k];
    lo0 += a * x[2 * col[k]];
    lo1 += a * x[2 * col[k] + 1];
  }
  if (FromZero) {
    x[2 * i] = (b[2 * i] - lo0) * invDiag[i];
    x[2 * i + 1] = (b[2 * i + 1] - lo1) * invDiag[i];
    return;
  }
  for (int32_t k = split[i]; k < A.start[i + 1]; ++k) {
    const double a = value[k];
    hi0 += a * x[2 * col[k]];
    hi1 += a * x[2 * col[k] + 1];
  }
  x[2 * i] += (b[2 * i] - lo0 - hi0) * invDiag[i];
  x[2 * i + 1] += (b[2 * i + 1] - lo1 - hi1) * invDiag[i];
}

/// One Gauss–Seidel sweep in the level's sweep order (SweepOrder): forward, every block's inner rows
/// (the blocks on all threads: an inner row reads only its own block, so they cannot race) and then the
/// border rows in ascending order; backward, the exact reverse. fromZero (forward only): x = 0 on entry.
/// The border rows are the only ones an inner row reads before the sweep writes them, so they are
/// zeroed first and the inner rows may skip everything at or above their own row.
void gaussSeidel(const CsrMatrix& A, const float* value, const SweepOrder& order, const std::vector<int32_t>& split,
                 const std::vector<double>& invDiag, const double* b, double* x, bool forward, bool fromZero) {
  const int32_t* sp = split.data();
  const double* inv = invDiag.data();
  const std::vector<int32_t>& border = order.border;
  auto inner = [&](std::size_t block, std::size_t, std::size_t) {
    const int32_t begin = order.blockStart[block], end = order.blockStart[block + 1];
    const int32_t* firstBorder = border.data() + order.blockBorder[block];
    const int32_t* lastBorder = border.data() + order.blockBorder[block + 1];
    if (forward) {
      const int32_t* next = firstBorder;  // the block's next border row at or after i
      for (int32_t i = begin; i < end; ++i) {
        if (next != lastBorder && *next == i) {
          ++next;
          continue;
        }
        if (fromZero) relaxRow<true>(A, value, sp, inv, b, x, i);
        else relaxRow<false>(A, value, sp, inv, b, x, i);
      }
    } else {
      const int32_t* next = lastBorder;  // one past the block's last border row at or before i
      for (int32_t i = end - 1; i >= begin; --i) {
        if (next != firstBorder && next[-1] == i) {
          --next;
          continue;
        }
        relaxRow<false>(A, value, sp, inv, b, x, i);
      }
    }
  };
  const std::size_t blocks = order.blockStart.size() - 1;
  if (forward) {
    if (fromZero)
      for (const int32_t i : border) x[2 * i] = x[2 * i + 1] = 0;
    detail::parallelFor(blocks, 1, inner);
    for (const int32_t i : border) relaxRow<false>(A, value, sp, inv, b, x, i);
  } else {
    for (auto it = border.rbegin(); it != border.rend(); ++it) relaxRow<false>(A, value, sp, inv, b, x, *it);
    detail::parallelFor(blocks, 1, inner);
  }
}

/// One damped Jacobi step x ← x + ω D⁻¹ (b − A x); tmp is work space of x's size.
void jacobi(const CsrMatrix& A, const std::vector<double>& invDiag, const double* b, double* x, double* tmp) {
  constexpr double omega = 2.0 / 3.0;
  A.multiply2(x, tmp);
  detail::forRowChunks(static_cast<size_t>(A.rows), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      x[2 * i] += omega * invDiag[i] * (b[2 * i] - tmp[2 * i]);
      x[2 * i + 1] += omega * invDiag[i] * (b[2 * i + 1] - tmp[2 * i + 1]);
    }
  });
}

}  // namespace

void AggregationMultigrid::Hierarchy::cycle(const Options& options, size_t l, const double* b, double* x) const {
  const Level& level = levels[l];
  const int32_t n = level.A.rows;
  if (l + 1 == levels.size()) {
    for (int32_t i = 0; i < n; ++i) {
      coarseRhs(i, 0) = b[2 * i];
      coarseRhs(i, 1) = b[2 * i + 1];
    }
    const Eigen::MatrixXd sol = coarse.solve(coarseRhs);
    for (int32_t i = 0; i < n; ++i) {
      x[2 * i] = sol(i, 0);
      x[2 * i + 1] = sol(i, 1);
    }
    return;
  }
  const bool gs = options.smoother == Smoother::GaussSeidel;
  if (!gs || options.preSweeps == 0) std::fill(x, x + 2 * static_cast<size_t>(n), 0.0);
  auto smooth = [&](bool forward, bool fromZero) {
    if (gs) gaussSeidel(level.A, level.a32.data(), level.order, level.split, level.invDiag, b, x, forward, fromZero);
    else jacobi(level.A, level.invDiag, b, x, level.tmp.data());
  };
  for (int s = 0; s < options.preSweeps; ++s) smooth(true, s == 0);
  // Residual r = b − A x, then restriction b_c = R r by the rows of R: each coarse row sums its fine
  // rows in ascending order (the sum a scatter through P's rows, row after row, would form).
  const Level& coarser = levels[l + 1];
  const CsrMatrix& A = level.A;
  const CsrMatrix& P = level.P;
  const CsrMatrix& R = level.R;
  double* r = level.tmp.data();
  const float* aValue = level.a32.data();
  const float* pValue = level.p32.data();
  const float* rValue = level.r32.data();
  detail::forRowChunks(static_cast<size_t>(n), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      double r0 = b[2 * i], r1 = b[2 * i + 1];
      for (int32_t k = A.start[i]; k < A.start[i + 1]; ++k) {
        const double a = aValue[k];
        const int32_t j = A.col[k];
        r0 -= a * x[2 * j];
        r1 -= a * x[2 * j + 1];
      }
      r[2 * i] = r0;
      r[2 * i + 1] = r1;
    }
  });
  double* bc = coarser.b.data();
  detail::forRowChunks(static_cast<size_t>(R.rows), [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      double s0 = 0, s1 = 0;
      for (int32_t k = R.start[c]; k < R.start[c + 1]; ++k) {
        const double p = rValue[k];
        const int32_t i = R.col[k];
        s0 += p * r[2 * i];
        s1 += p * r[2 * i + 1];
      }
      bc[2 * c] = s0;
      bc[2 * c + 1] = s1;
    }
  });
  double* xc = coarser.x.data();
  cycle(options, l + 1, bc, xc);
  // Coarse correction x += P x_c.
  detail::forRowChunks(static_cast<size_t>(n), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      double s0 = 0, s1 = 0;
      for (int32_t k = P.start[i]; k < P.start[i + 1]; ++k) {
        const double p = pValue[k];
        const int32_t c = P.col[k];
        s0 += p * xc[2 * c];
        s1 += p * xc[2 * c + 1];
      }
      x[2 * i] += s0;
      x[2 * i + 1] += s1;
    }
  });
  for (int s = 0; s < options.postSweeps; ++s) smooth(false, false);
}

void AggregationMultigrid::apply(const double* b, double* x) const { hierarchy_->cycle(options_, 0, b, x); }

}  // namespace straightest
