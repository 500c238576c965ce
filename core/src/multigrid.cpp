#include "straightest/multigrid.hpp"

#include <cmath>

namespace straightest {
namespace {

using Matrix = AggregationMultigrid::Matrix;

/// Greedy aggregation on the strong-connection graph; returns the aggregate of every node.
std::vector<int> aggregate(const Matrix& A, int& count) {
  const int n = static_cast<int>(A.rows());
  Eigen::VectorXd diag = A.diagonal().cwiseAbs();
  auto strong = [&](int i, int j, double a) {
    return i != j && std::abs(a) >= AggregationMultigrid::kStrength * std::sqrt(diag[i] * diag[j]);
  };
  std::vector<int> agg(n, -1);
  count = 0;
  // Pass 1: roots whose strong neighbours are all free take them all.
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    bool free = true;
    for (Matrix::InnerIterator it(A, i); it && free; ++it)
      if (strong(i, static_cast<int>(it.col()), it.value()) && agg[it.col()] >= 0) free = false;
    if (!free) continue;
    agg[i] = count;
    for (Matrix::InnerIterator it(A, i); it; ++it)
      if (strong(i, static_cast<int>(it.col()), it.value())) agg[it.col()] = count;
    ++count;
  }
  // Pass 2: the rest join the aggregate of their strongest aggregated neighbour.
  std::vector<int> joined(agg);
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    double best = 0;
    for (Matrix::InnerIterator it(A, i); it; ++it)
      if (strong(i, static_cast<int>(it.col()), it.value()) && agg[it.col()] >= 0 && std::abs(it.value()) > best) {
        best = std::abs(it.value());
        joined[i] = agg[it.col()];
      }
  }
  agg = joined;
  // Pass 3: isolated leftovers become aggregates of their own.
  for (int i = 0; i < n; ++i)
    if (agg[i] < 0) agg[i] = count++;
  return agg;
}

}  // namespace

std::vector<Eigen::Index> AggregationMultigrid::sizes() const {
  std::vector<Eigen::Index> s;
  for (const Level& l : levels_) s.push_back(l.A.rows());
  return s;
}

void AggregationMultigrid::build(Matrix A) {
  levels_.clear();
  info_ = Eigen::Success;
  while (true) {
    Level level;
    level.A = std::move(A);
    level.A.makeCompressed();
    const Eigen::Index n = level.A.rows();
    level.invDiag = level.A.diagonal();
    for (Eigen::Index i = 0; i < n; ++i) {
      if (level.invDiag[i] == 0) {
        info_ = Eigen::NumericalIssue;
        return;
      }
      level.invDiag[i] = 1.0 / level.invDiag[i];
    }
    if (n <= kCoarseSize || levels_.size() >= 25) {
      levels_.push_back(std::move(level));
      break;
    }
    int count = 0;
    const std::vector<int> agg = aggregate(level.A, count);
    if (count >= n || count == 0) {  // no coarsening possible: stop here
      levels_.push_back(std::move(level));
      break;
    }
    // Tentative prolongator, smoothed by one damped Jacobi step: P = (I − ω D⁻¹ A) P0.
    Matrix P0(n, count);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(n);
    for (Eigen::Index i = 0; i < n; ++i) t.emplace_back(static_cast<int>(i), agg[i], 1.0);
    P0.setFromTriplets(t.begin(), t.end());
    const double omega = 2.0 / 3.0;
    const Matrix DA = level.invDiag.asDiagonal() * level.A;
    const Matrix DAP0 = DA * P0;
    level.P = P0 - omega * DAP0;
    level.P.prune(0.0);
    level.R = level.P.transpose();
    const Matrix AP = level.A * level.P;
    A = level.R * AP;
    levels_.push_back(std::move(level));
  }
  coarse_ = std::make_shared<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
  coarse_->compute(Eigen::SparseMatrix<double>(levels_.back().A));
  if (coarse_->info() != Eigen::Success) info_ = coarse_->info();
}

void AggregationMultigrid::cycle(size_t l, const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const Level& level = levels_[l];
  if (l + 1 == levels_.size()) {
    x = coarse_->solve(b);
    return;
  }
  const double omega = 2.0 / 3.0;
  x = omega * level.invDiag.cwiseProduct(b);  // first smoothing step from x = 0
  Eigen::VectorXd r;
  for (int s = 1; s < 2; ++s) {
    r = b - level.A * x;
    x += omega * level.invDiag.cwiseProduct(r);
  }
  r = b - level.A * x;
  Eigen::VectorXd coarseX;
  cycle(l + 1, level.R * r, coarseX);
  x += level.P * coarseX;
  for (int s = 0; s < 2; ++s) {
    r = b - level.A * x;
    x += omega * level.invDiag.cwiseProduct(r);
  }
}

}  // namespace straightest
