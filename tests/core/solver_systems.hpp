// Linear systems for the solver tests: the parameterization's own I − W with a circle boundary (an
// M-matrix whose condition grows with the mesh, the case the solvers are built for), small
// hand-made matrices, and dense copies to check the sparse kernels against.
#pragma once
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "straightest/param/boundary_map.hpp"
#include "straightest/param/interior_weights.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest::testing {

/// I − W for the interior of `mesh` with shape-preserving weights and a circle boundary, and the two
/// interleaved right-hand sides.
inline InteriorSystem circleSystem(const TriMesh& mesh) {
  const InteriorWeights W = interiorWeights(mesh, WeightKind::ShapePreserving);
  const BoundaryMap boundary = circleBoundary(mesh);
  std::vector<Vec2> uv(mesh.numVertices(), Vec2{0, 0});
  for (size_t i = 0; i < boundary.loop.size(); ++i) uv[boundary.loop[i]] = boundary.polygon[i];
  return assembleInteriorSystem(W, uv);
}

using Dense = std::vector<std::vector<double>>;

inline Dense toDense(const CsrMatrix& a) {
  Dense d(a.rows, std::vector<double>(a.cols, 0.0));
  for (int32_t r = 0; r < a.rows; ++r)
    for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) d[r][a.col[k]] += a.value[k];
  return d;
}

/// A matrix from its rows of (column, value) entries, in the given order.
inline CsrMatrix fromRows(int32_t cols, const std::vector<std::vector<std::pair<int32_t, double>>>& rows) {
  CsrMatrix m;
  m.rows = static_cast<int32_t>(rows.size());
  m.cols = cols;
  for (const auto& row : rows) {
    for (const auto& [c, v] : row) {
      m.col.push_back(c);
      m.value.push_back(v);
    }
    m.start.push_back(static_cast<int32_t>(m.col.size()));
  }
  return m;
}

/// |b − A x| / |b| of column c (0 or 1) of interleaved vectors.
inline double columnResidual(const CsrMatrix& A, const std::vector<double>& b, const std::vector<double>& x, int c) {
  std::vector<double> Ax(x.size());
  A.multiply2(x.data(), Ax.data());
  double r2 = 0, b2 = 0;
  for (size_t i = c; i < x.size(); i += 2) {
    r2 += (Ax[i] - b[i]) * (Ax[i] - b[i]);
    b2 += b[i] * b[i];
  }
  return std::sqrt(r2 / b2);
}

/// The same system with its unknowns renumbered at random (row and column i of the result are row and
/// column order[i] of s): a numbering where neighbours are scattered, unlike a mesh's.
inline InteriorSystem scattered(const InteriorSystem& s, unsigned seed) {
  std::vector<int32_t> order(s.A.rows), position(s.A.rows);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  for (int32_t i = 0; i < s.A.rows; ++i) position[order[i]] = i;
  InteriorSystem out;
  out.A.rows = out.A.cols = s.A.rows;
  for (const int32_t old : order) {
    for (int32_t k = s.A.start[old]; k < s.A.start[old + 1]; ++k) {
      out.A.col.push_back(position[s.A.col[k]]);
      out.A.value.push_back(s.A.value[k]);
    }
    out.A.start.push_back(static_cast<int32_t>(out.A.col.size()));
    out.rhs.push_back(s.rhs[2 * static_cast<size_t>(old)]);
    out.rhs.push_back(s.rhs[2 * static_cast<size_t>(old) + 1]);
  }
  return out;
}

}  // namespace straightest::testing
