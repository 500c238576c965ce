// The compressed-row kernels agree with the dense matrices they stand for; the interior weights and
// their system are such matrices.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

#include "../../core/solver/src/row_accumulator.hpp"
#include "solver_systems.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {
namespace {

using testing::Dense;
using testing::fromRows;
using testing::toDense;

/// A random rows × cols matrix with unsorted rows and some repeated columns (which count as a sum).
CsrMatrix randomMatrix(int32_t rows, int32_t cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int32_t> column(0, cols - 1), length(0, 5);
  std::uniform_real_distribution<double> value(-2, 2);
  std::vector<std::vector<std::pair<int32_t, double>>> entries(rows);
  for (auto& row : entries) {
    for (int32_t k = length(rng); k > 0; --k) row.push_back({column(rng), value(rng)});
    if (!row.empty()) row.push_back({row.front().first, value(rng)});  // a repeated column
  }
  return fromRows(cols, entries);
}

void expectNear(const Dense& a, const Dense& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t r = 0; r < a.size(); ++r) {
    ASSERT_EQ(a[r].size(), b[r].size());
    for (size_t c = 0; c < a[r].size(); ++c) EXPECT_NEAR(a[r][c], b[r][c], 1e-12) << r << "," << c;
  }
}

TEST(CsrMatrix, TwoColumnProductIsTheDenseProductOfEachColumn) {
  const CsrMatrix a = randomMatrix(13, 9, 1);
  const Dense d = toDense(a);
  std::vector<double> x(2 * 9), y(2 * 13);
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::sin(1.0 + i);
  a.multiply2(x.data(), y.data());
  for (int32_t r = 0; r < 13; ++r)
    for (int c = 0; c < 2; ++c) {
      double s = 0;
      for (int32_t j = 0; j < 9; ++j) s += d[r][j] * x[2 * j + c];
      EXPECT_NEAR(y[2 * r + c], s, 1e-12);
    }
}

TEST(CsrMatrix, TransposeSwapsRowsAndColumnsAndSortsThem) {
  const CsrMatrix a = randomMatrix(11, 7, 2);
  const CsrMatrix t = transpose(a);
  ASSERT_EQ(t.rows, 7);
  ASSERT_EQ(t.cols, 11);
  EXPECT_EQ(t.nonZeros(), a.nonZeros());
  const Dense da = toDense(a), dt = toDense(t);
  for (int32_t r = 0; r < 11; ++r)
    for (int32_t c = 0; c < 7; ++c) EXPECT_EQ(dt[c][r], da[r][c]);
  for (int32_t r = 0; r < t.rows; ++r)
    for (int32_t k = t.start[r] + 1; k < t.start[r + 1]; ++k) EXPECT_LE(t.col[k - 1], t.col[k]);
}

TEST(CsrMatrix, ProductIsTheDenseProduct) {
  const CsrMatrix a = randomMatrix(10, 8, 3), b = randomMatrix(8, 12, 4);
  const CsrMatrix c = multiply(a, b);
  ASSERT_EQ(c.rows, 10);
  ASSERT_EQ(c.cols, 12);
  const Dense da = toDense(a), db = toDense(b);
  Dense expected(10, std::vector<double>(12, 0.0));
  for (int32_t i = 0; i < 10; ++i)
    for (int32_t k = 0; k < 8; ++k)
      for (int32_t j = 0; j < 12; ++j) expected[i][j] += da[i][k] * db[k][j];
  expectNear(toDense(c), expected);
  // Each row holds a column at most once.
  for (int32_t r = 0; r < c.rows; ++r)
    for (int32_t k = c.start[r]; k < c.start[r + 1]; ++k)
      for (int32_t q = k + 1; q < c.start[r + 1]; ++q) EXPECT_NE(c.col[k], c.col[q]);
}

TEST(CsrMatrix, ProductBuiltInPiecesOnSeveralThreadsIsTheRowByRowProduct) {
  // 50k rows: the product is built in several pieces (row_accumulator.hpp's buildRows), on 1 and 3
  // threads; every row must be exactly the product of that row alone.
  const CsrMatrix a = randomMatrix(50000, 3000, 5), b = randomMatrix(3000, 4000, 6);
  for (int threads : {1, 3}) {
    setThreadCount(threads);
    const CsrMatrix c = multiply(a, b);
    ASSERT_TRUE(wellFormed(c));
    ASSERT_EQ(c.rows, a.rows);
    for (int32_t r = 0; r < a.rows; r += 997) {
      CsrMatrix row;
      row.rows = 1;
      row.cols = a.cols;
      row.col.assign(a.col.begin() + a.start[r], a.col.begin() + a.start[r + 1]);
      row.value.assign(a.value.begin() + a.start[r], a.value.begin() + a.start[r + 1]);
      row.start.push_back(static_cast<int32_t>(row.col.size()));
      const CsrMatrix alone = multiply(row, b);
      ASSERT_EQ(c.start[r + 1] - c.start[r], alone.start[1]) << "row " << r;
      for (int32_t k = 0; k < alone.start[1]; ++k) {
        EXPECT_EQ(c.col[c.start[r] + k], alone.col[k]) << "row " << r;
        EXPECT_EQ(c.value[c.start[r] + k], alone.value[k]) << "row " << r;
      }
    }
  }
  setThreadCount(0);
}

TEST(CsrMatrix, ProductWithARightFactorLeftInItsPiecesIsTheProductWithItJoined) {
  // The multigrid's Pᵀ (A P) reads A P in the pieces it was built in; it must be the same matrix, entry
  // for entry, as the product with the pieces joined. 40k rows: several pieces; the left factor's rows
  // are unsorted and repeat columns, so the step from one entry's piece to the next goes both ways.
  const CsrMatrix x = randomMatrix(40000, 2000, 7), y = randomMatrix(2000, 3000, 8);
  const CsrMatrix a = randomMatrix(3000, 40000, 9);
  for (int threads : {1, 3}) {
    setThreadCount(threads);
    const RowPieces pieces = multiplyInPieces(x, y, 0);
    ASSERT_GE(pieces.parts.size(), 2u);
    const CsrMatrix fromPieces = multiply(a, pieces, 0);
    const CsrMatrix fromJoined = multiply(a, multiply(x, y));
    ASSERT_TRUE(wellFormed(fromPieces));
    EXPECT_EQ(fromPieces.rows, fromJoined.rows);
    EXPECT_EQ(fromPieces.cols, fromJoined.cols);
    EXPECT_EQ(fromPieces.start, fromJoined.start);
    EXPECT_EQ(fromPieces.col, fromJoined.col);
    EXPECT_EQ(fromPieces.value, fromJoined.value);
  }
  setThreadCount(0);
}

TEST(CsrMatrix, SortedRowsKeepTheMatrixAndSplitAtTheDiagonal) {
  CsrMatrix a = randomMatrix(15, 15, 5);
  const Dense before = toDense(a);
  const std::vector<int32_t> split = sortRows(a);
  EXPECT_EQ(toDense(a), before);
  ASSERT_EQ(split.size(), 15u);
  for (int32_t r = 0; r < a.rows; ++r) {
    for (int32_t k = a.start[r] + 1; k < a.start[r + 1]; ++k) EXPECT_LE(a.col[k - 1], a.col[k]);
    for (int32_t k = a.start[r]; k < a.start[r + 1]; ++k) EXPECT_EQ(k < split[r], a.col[k] < r) << r;
  }
}

TEST(CsrMatrix, WellFormedTellsArraysThatDescribeAMatrixFromOnesThatDoNot) {
  CsrMatrix a = randomMatrix(6, 4, 6);
  EXPECT_TRUE(wellFormed(a));
  EXPECT_TRUE(wellFormed(CsrMatrix{}));  // 0 × 0
  CsrMatrix outside = a;
  outside.col.back() = 4;  // column 4 of a 4-column matrix
  EXPECT_FALSE(wellFormed(outside));
  CsrMatrix backwards = fromRows(3, {{{0, 1.0}}, {{1, 1.0}}, {{2, 1.0}}});
  ASSERT_TRUE(wellFormed(backwards));
  backwards.start[1] = 3;  // rows [0, 3) and [3, 2)
  EXPECT_FALSE(wellFormed(backwards));
  CsrMatrix short_ = a;
  short_.value.pop_back();
  EXPECT_FALSE(wellFormed(short_));
  CsrMatrix rows = a;
  rows.rows = 7;
  EXPECT_FALSE(wellFormed(rows));
}

TEST(CsrMatrix, DiagonalSumsTheDiagonalEntriesOfEachRow) {
  const CsrMatrix a = fromRows(3, {{{0, 2.0}, {1, 5.0}, {0, 0.5}}, {{2, 1.0}}, {{2, -3.0}, {0, 4.0}}});
  EXPECT_EQ(diagonal(a), (std::vector<double>{2.5, 0.0, -3.0}));
}

TEST(InteriorWeights, AreRowsOfOneRingNeighboursSummingToOneAndTheirSystemKeepsConstants) {
  const TriMesh mesh = makeSample("face").value();
  std::set<std::pair<int32_t, int32_t>> edges;
  for (const Triangle& t : mesh.triangles())
    for (int k = 0; k < 3; ++k) edges.insert({t[k], t[(k + 1) % 3]}), edges.insert({t[(k + 1) % 3], t[k]});
  for (WeightKind kind : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Cotan, WeightKind::Uniform}) {
    const InteriorWeights W = interiorWeights(mesh, kind);
    ASSERT_EQ(W.weights.rows, static_cast<int32_t>(W.rows.size()));
    ASSERT_EQ(W.weights.cols, mesh.numVertices());
    for (int32_t r = 0; r < W.weights.rows; ++r) {
      double sum = 0;
      for (int32_t k = W.weights.start[r]; k < W.weights.start[r + 1]; ++k) {
        sum += W.weights.value[k];
        EXPECT_TRUE(edges.count({W.rows[r], W.weights.col[k]})) << "not a neighbour";
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << weightKindName(kind);
    }
    // Every vertex fixed at (c, d) outside: the interior at (c, d) solves the system exactly.
    const std::vector<Vec2> fixed(mesh.numVertices(), Vec2{0.3, -1.7});
    const InteriorSystem s = assembleInteriorSystem(W, fixed);
    ASSERT_EQ(s.A.rows, W.weights.rows);
    ASSERT_EQ(s.A.cols, W.weights.rows);
    std::vector<double> x(2 * static_cast<size_t>(s.A.rows)), Ax(x.size());
    for (size_t i = 0; i < x.size(); i += 2) x[i] = 0.3, x[i + 1] = -1.7;
    s.A.multiply2(x.data(), Ax.data());
    for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(Ax[i], s.rhs[i], 1e-12);
  }
}

TEST(InteriorWeights, ShapePreservingOnesReproduceThePlanarCentreOfARingOfAnyValence) {
  // Floater's weights have linear precision: for a flat one ring the polar map is the ring itself (up
  // to a rotation), so Σ w_k p_k = p. Rings of 3 to 40 neighbours at random angles (gaps below π) and
  // distances; each neighbour's opposite segment is searched among all the others.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int d = 3; d <= 40; ++d) {
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<double> gaps(d);
      double total = 0;
      for (double& g : gaps) total += g = 0.2 + unit(rng);
      const Vec3 centre{0.3, -0.2, 0};
      std::vector<Vec3> positions{centre};
      std::vector<Triangle> triangles;
      double angle = unit(rng);
      bool gapsBelowPi = true;
      for (int k = 0; k < d; ++k) {
        gapsBelowPi = gapsBelowPi && gaps[k] * kTwoPi / total < kPi - 1e-3;
        const double r = 0.5 + 2 * unit(rng);
        positions.push_back(centre + Vec3{r * std::cos(angle), r * std::sin(angle), 0});
        angle += gaps[k] * kTwoPi / total;
        triangles.push_back({0, 1 + k, 1 + (k + 1) % d});
      }
      if (!gapsBelowPi) continue;
      const TriMesh mesh = TriMesh::build(positions, triangles).value();
      const InteriorWeights W = interiorWeights(mesh, WeightKind::ShapePreserving);
      ASSERT_EQ(W.rows, std::vector<int32_t>{0});
      EXPECT_EQ(W.uniformFallbacks, 0) << d;
      Vec3 sum{};
      for (int32_t k = W.weights.start[0]; k < W.weights.start[1]; ++k) {
        EXPECT_GT(W.weights.value[k], -1e-12) << d;
        sum = sum + positions[W.weights.col[k]] * W.weights.value[k];
      }
      EXPECT_NEAR(sum[0], centre[0], 1e-12) << d;
      EXPECT_NEAR(sum[1], centre[1], 1e-12) << d;
    }
  }
}

}  // namespace
}  // namespace straightest
