// slim_global_step.cpp — SLIM's global step: the weighted least-squares system, solved directly or by CG.
#include "slim_global_step.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>

#include "straightest/solver/eigen_bridge.hpp"

namespace straightest {
namespace {

/// Per-column dot products of two interleaved vectors.
std::array<double, 2> dot2(const std::vector<double>& a, const std::vector<double>& b) {
  std::array<double, 2> s{0, 0};
  for (size_t i = 0; i < a.size(); i += 2) {
    s[0] += a[i] * b[i];
    s[1] += a[i + 1] * b[i + 1];
  }
  return s;
}

}  // namespace

SlimGlobalStep::SlimGlobalStep(const TriMesh& mesh, int32_t directSize)
    : mesh_(mesh), n_(mesh.numVertices()), directSize_(directSize) {
  std::vector<std::vector<int32_t>> rows(n_);
  for (const Triangle& t : mesh.triangles())
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) rows[t[r]].push_back(t[c]);
  matrix_.rows = matrix_.cols = n_;
  matrix_.start.assign(1, 0);
  for (int32_t v = 0; v < n_; ++v) {
    std::vector<int32_t>& row = rows[v];
    row.push_back(v);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    matrix_.col.insert(matrix_.col.end(), row.begin(), row.end());
    matrix_.start.push_back(static_cast<int32_t>(matrix_.col.size()));
    std::vector<int32_t>().swap(row);
  }
  matrix_.value.assign(matrix_.col.size(), 0.0);
  slots_.resize(9 * size_t(mesh.numFaces()));
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) slots_[9 * size_t(f) + 3 * r + c] = slot(t[r], t[c]);
  }
  diagonal_.resize(n_);
  for (int32_t v = 0; v < n_; ++v) diagonal_[v] = slot(v, v);
}

bool SlimGlobalStep::solve(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
                           const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv, std::vector<Vec2>& next) {
  assemble(gradients, weights, rotations, uv);
  std::vector<double> x(2 * size_t(n_));
  for (int32_t v = 0; v < n_; ++v) {
    x[2 * v] = uv[v].x;
    x[2 * v + 1] = uv[v].y;
  }
  bool solved = false;
  lastIterations_ = 0;
  for (int attempt = 0; attempt < 2 && !solved && n_ > directSize_; ++attempt) {
    if (!preconditionerCurrent_) {
      auto built = multigrid_.compute(matrix_);
      if (!built || !built.value()) break;
      preconditionerCurrent_ = true;
    }
    std::vector<double> trial = x;
    const int iterations = conjugateGradients(trial);
    lastIterations_ += std::max(iterations, 0);
    solved = iterations >= 0;
    if (solved) x.swap(trial);
    preconditionerCurrent_ = solved && iterations <= kStaleIterations;
  }
  if (!solved && !directSolve(x)) return false;
  next.resize(n_);
  for (int32_t v = 0; v < n_; ++v) next[v] = {x[2 * v], x[2 * v + 1]};
  for (const Vec2& q : next)
    if (!isFinite(q)) return false;
  return true;
}

int32_t SlimGlobalStep::slot(int32_t row, int32_t col) const {
  const auto begin = matrix_.col.begin() + matrix_.start[row], end = matrix_.col.begin() + matrix_.start[row + 1];
  return static_cast<int32_t>(std::lower_bound(begin, end, col) - matrix_.col.begin());
}

void SlimGlobalStep::assemble(const std::vector<FaceGradient>& gradients, const std::vector<Mat2>& weights,
                              const std::vector<Mat2>& rotations, const std::vector<Vec2>& uv) {
  std::vector<double>& value = matrix_.value;
  std::fill(value.begin(), value.end(), 0.0);
  rhs_.assign(2 * size_t(n_), 0.0);
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
      rhs_[2 * t[r]] += g.area * (mgx[r] * rot.a + mgy[r] * rot.b);
      rhs_[2 * t[r] + 1] += g.area * (mgx[r] * rot.c + mgy[r] * rot.d);
    }
  }
  double meanDiagonal = 0;
  for (int32_t v = 0; v < n_; ++v) meanDiagonal += value[diagonal_[v]];
  meanDiagonal /= std::max(1, n_);
  const double proximal = kProximalRel * (meanDiagonal > 0 ? meanDiagonal : 1);
  for (int32_t v = 0; v < n_; ++v) {
    value[diagonal_[v]] += proximal;
    rhs_[2 * v] += proximal * uv[v].x;
    rhs_[2 * v + 1] += proximal * uv[v].y;
  }
}

int SlimGlobalStep::conjugateGradients(std::vector<double>& x) const {
  const size_t size = x.size();
  std::vector<double> r(size), z(size), p(size), q(size);
  matrix_.multiply2(x.data(), q.data());
  for (size_t i = 0; i < size; ++i) r[i] = rhs_[i] - q[i];
  const std::array<double, 2> rr0 = dot2(r, r), bb = dot2(rhs_, rhs_);
  std::array<double, 2> target;
  for (int c = 0; c < 2; ++c)
    target[c] = std::max(kSolveReduction * kSolveReduction * rr0[c], 1e-28 * bb[c]);  // squared norms
  multigrid_.apply(r.data(), z.data());
  p = z;
  std::array<double, 2> rz = dot2(r, z);
  for (int it = 0; it <= kMaxIterations; ++it) {
    const std::array<double, 2> rr = dot2(r, r);
    if (!std::isfinite(rr[0] + rr[1])) return -1;
    const bool done[2] = {rr[0] <= target[0], rr[1] <= target[1]};
    if (done[0] && done[1]) return it;
    if (it == kMaxIterations) break;
    matrix_.multiply2(p.data(), q.data());
    const std::array<double, 2> pq = dot2(p, q);
    for (int c = 0; c < 2; ++c) {
      if (done[c]) continue;  // a converged column stays as it is
      const double alpha = rz[c] / pq[c];
      for (size_t i = c; i < size; i += 2) {
        x[i] += alpha * p[i];
        r[i] -= alpha * q[i];
      }
    }
    multigrid_.apply(r.data(), z.data());
    const std::array<double, 2> rzNext = dot2(r, z);
    for (int c = 0; c < 2; ++c) {
      if (done[c]) continue;
      const double beta = rzNext[c] / rz[c];
      for (size_t i = c; i < size; i += 2) p[i] = z[i] + beta * p[i];
      rz[c] = rzNext[c];
    }
  }
  return -1;
}

struct SlimGlobalStep::Cholesky {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
};

SlimGlobalStep::~SlimGlobalStep() = default;

bool SlimGlobalStep::directSolve(std::vector<double>& x) {
  // The matrix is symmetric, so its compressed rows are its compressed columns: Eigen reads them as is.
  const Eigen::Map<const Eigen::SparseMatrix<double>> a(n_, n_, matrix_.nonZeros(), matrix_.start.data(),
                                                        matrix_.col.data(), matrix_.value.data());
  if (!cholesky_) {
    cholesky_ = std::make_unique<Cholesky>();
    cholesky_->factor.analyzePattern(a);  // the ordering depends on the pattern only: once
  }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>& cholesky = cholesky_->factor;
  cholesky.factorize(a);
  if (cholesky.info() != Eigen::Success) return false;
  solveInterleaved(cholesky, rhs_, x);
  return true;
}

}  // namespace straightest
