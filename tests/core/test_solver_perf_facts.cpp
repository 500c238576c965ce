// Facts the fast paths of the parameterization rely on: the two-column multigrid BiCGSTAB gives the
// direct solve's answer in a few iterations, its setup reports progress and can be cancelled, the
// solve stage can be cancelled, and the bucketed Dijkstra behind defaultSource gives the distances of
// a textbook binary-heap Dijkstra bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>

#include "straightest/boundary_map.hpp"
#include "straightest/geodesic_distance.hpp"
#include "straightest/interior_weights.hpp"
#include "straightest/multigrid.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"

namespace straightest {
namespace {

/// I − W for the interior of `mesh` with a circle boundary, and the two interleaved right-hand sides.
void circleSystem(const TriMesh& mesh, CsrMatrix& A, std::vector<double>& rhs) {
  const InteriorWeights W = interiorWeights(mesh, WeightKind::ShapePreserving);
  const BoundaryMap boundary = circleBoundary(mesh);
  std::vector<Vec2> uv(mesh.numVertices(), Vec2{0, 0});
  for (size_t i = 0; i < boundary.loop.size(); ++i) uv[boundary.loop[i]] = boundary.polygon[i];
  assembleInteriorSystem(W, uv, A, rhs);
}

TEST(SolverFacts, TwoColumnMultigridBiCGSTABMatchesSparseLUInFewIterations) {
  CsrMatrix A;
  std::vector<double> rhs;
  circleSystem(makeHeightField(100), A, rhs);
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A.toEigen());
  ASSERT_EQ(lu.info(), Eigen::Success);
  Eigen::MatrixXd b(A.rows, 2);
  for (int32_t r = 0; r < A.rows; ++r) b.row(r) << rhs[2 * r], rhs[2 * r + 1];
  const Eigen::MatrixXd exact = lu.solve(b);

  AggregationMultigrid mg;
  std::vector<double> fractions;
  ASSERT_TRUE(mg.compute(A, [&](double f) {
    fractions.push_back(f);
    return true;
  }));
  EXPECT_GE(mg.levels(), 3);
  EXPECT_LE(mg.sizes().back(), AggregationMultigrid::kCoarseSize);
  ASSERT_FALSE(fractions.empty());
  for (size_t i = 1; i < fractions.size(); ++i) EXPECT_GE(fractions[i], fractions[i - 1]);
  EXPECT_EQ(fractions.back(), 1.0);

  std::vector<double> x(rhs.size(), 0.0);
  int calls = 0;
  const KrylovStats stats = solveTwoColumns(mg.matrix(), mg, rhs, x, 1e-10, 1000, [&](int it, double) {
    EXPECT_EQ(it, ++calls);
    return true;
  });
  ASSERT_TRUE(stats.converged);
  EXPECT_LE(stats.iterations, 15);  // ~8–10 seen at 10k–1M vertices; thousands without multigrid
  EXPECT_EQ(calls, stats.iterations);
  for (int c = 0; c < 2; ++c) EXPECT_LE(stats.relativeResidual[c], 1e-10);
  for (int32_t r = 0; r < A.rows; ++r) {
    ASSERT_NEAR(x[2 * r], exact(r, 0), 1e-8);
    ASSERT_NEAR(x[2 * r + 1], exact(r, 1), 1e-8);
  }
}

TEST(SolverFacts, ColumnsConvergeIndependentlyAndAZeroColumnIsSolvedExactly) {
  CsrMatrix A;
  std::vector<double> rhs;
  circleSystem(makeHeightField(40), A, rhs);
  for (size_t i = 1; i < rhs.size(); i += 2) rhs[i] = 0;  // v column: b = 0 → x = 0
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.compute(A));
  std::vector<double> x(rhs.size(), 0.25);
  const KrylovStats stats = solveTwoColumns(mg.matrix(), mg, rhs, x, 1e-10, 1000);
  ASSERT_TRUE(stats.converged);
  for (size_t i = 1; i < x.size(); i += 2) ASSERT_EQ(x[i], 0.0);
  std::vector<double> Ax(x.size());
  A.multiply2(x.data(), Ax.data());
  double r2 = 0, b2 = 0;
  for (size_t i = 0; i < x.size(); i += 2) {
    r2 += (Ax[i] - rhs[i]) * (Ax[i] - rhs[i]);
    b2 += rhs[i] * rhs[i];
  }
  EXPECT_LT(std::sqrt(r2 / b2), 1e-9);
}

TEST(SolverFacts, MultigridSetupAndSolveStageCanBeCancelled) {
  CsrMatrix A;
  std::vector<double> rhs;
  circleSystem(makeHeightField(60), A, rhs);
  AggregationMultigrid mg;
  EXPECT_FALSE(mg.compute(A, [](double) { return false; }));
  EXPECT_FALSE(mg.ok());

  const TriMesh mesh = makeHeightField(60);
  bool setupReported = false;
  auto r = parameterize(mesh, {}, [&](const char* stage, double fraction) {
    if (std::string(stage) != "solve") return true;
    setupReported = setupReported || (fraction > 0 && fraction <= 0.2);
    return fraction < 0.5;  // cancel once the iterations are half way
  });
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::Cancelled);
  EXPECT_TRUE(setupReported);
}

/// The textbook version: binary heap of (distance, vertex), rotating around each vertex on the mesh.
std::vector<double> referenceDijkstra(const TriMesh& mesh, const std::vector<int32_t>& sources) {
  std::vector<double> dist(mesh.numVertices(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int32_t s : sources) {
    dist[s] = 0;
    queue.push({0.0, s});
  }
  auto relax = [&](double d, int32_t v, int32_t w) {
    const double nd = d + norm(mesh.position(w) - mesh.position(v));
    if (nd < dist[w]) {
      dist[w] = nd;
      queue.push({nd, w});
    }
  };
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    const int32_t first = mesh.vertexHalfedge(v);
    for (int32_t h = first; h >= 0;) {
      relax(d, v, mesh.head(h));
      const int32_t p = TriMesh::prev(h);
      if (mesh.twin(p) < 0) relax(d, v, mesh.tail(p));
      h = mesh.twin(p);
      if (h == first) break;
    }
  }
  return dist;
}

TEST(SolverFacts, BucketedDijkstraGivesTheBinaryHeapDistancesExactly) {
  for (const TriMesh& mesh : {makeHeightField(50), makeSample("face").value(), makeSample("cap").value()}) {
    std::vector<int32_t> boundary;
    for (const auto& loop : mesh.boundaryLoops()) boundary.insert(boundary.end(), loop.begin(), loop.end());
    if (boundary.empty()) boundary.push_back(0);
    const std::vector<double> fast = dijkstraDistances(mesh, boundary);
    const std::vector<double> slow = referenceDijkstra(mesh, boundary);
    ASSERT_EQ(fast.size(), slow.size());
    for (size_t v = 0; v < fast.size(); ++v) ASSERT_EQ(fast[v], slow[v]) << v;
  }
}

}  // namespace
}  // namespace straightest
