// The comparison table: every boundary × weights as parameterize computes it, and the best row by
// the rule boundary 'auto' uses.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"
#include "straightest/param/compare_parameterizations.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

const std::vector<BoundaryKind> kKinds = {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square,
                                          BoundaryKind::Free};
const std::vector<WeightKind> kWeights = {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Cotan,
                                          WeightKind::Uniform};

TEST(PreferredMap, BijectiveFirstThenLessStretchThenFewerBadTriangles) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(preferredMap(5.0, 0, inf, 0));  // bijective beats not, whatever the numbers
  EXPECT_FALSE(preferredMap(inf, 0, 5.0, 3));
  EXPECT_TRUE(preferredMap(1.1, 0, 1.2, 0));
  EXPECT_FALSE(preferredMap(1.2, 0, 1.1, 0));
  EXPECT_FALSE(preferredMap(1.1, 0, 1.1, 0));  // a tie keeps the incumbent
  EXPECT_TRUE(preferredMap(inf, 2, inf, 3));
  EXPECT_FALSE(preferredMap(inf, 3, inf, 3));
}

TEST(CompareParameterizations, EveryCellIsTheParameterizationAndBestIsWhatAutoPicks) {
  const TriMesh mesh = makeSample("face").value();
  const Comparison c = compareParameterizations(mesh, std::nullopt, kKinds, kWeights).value();
  ASSERT_EQ(c.rows.size(), kKinds.size() * kWeights.size());
  for (size_t b = 0; b < kKinds.size(); ++b)
    for (size_t w = 0; w < kWeights.size(); ++w) {
      const ComparisonRow& row = c.rows[b * kWeights.size() + w];
      EXPECT_EQ(row.boundary, kKinds[b]);
      EXPECT_EQ(row.weights, kWeights[w]);
      ASSERT_FALSE(row.error) << row.error->message;
      ParamOptions options;
      options.boundary = kKinds[b];
      options.weights = kWeights[w];
      const Parameterization p = parameterize(mesh, options).value();
      EXPECT_EQ(row.l2, p.metrics.l2);
      EXPECT_EQ(row.linf, p.metrics.linf);
      EXPECT_EQ(row.flipped, p.metrics.flipped);
      EXPECT_EQ(row.overlaps, p.metrics.overlaps);
      EXPECT_EQ(row.bijective, p.metrics.bijective);
      EXPECT_EQ(row.init, p.init);  // free: the same start (measured if bijective, else circle)
      EXPECT_EQ(row.init.has_value(), kKinds[b] == BoundaryKind::Free);
      if (row.init) {
        EXPECT_EQ(row.iterations, p.iterations);
      }
      EXPECT_GE(row.timeMs, 0);
    }
  ASSERT_GE(c.best, 0);
  for (const ComparisonRow& row : c.rows)
    EXPECT_FALSE(preferredMap(row.l2, row.flipped + row.degenerate, c.rows[c.best].l2,
                              c.rows[c.best].flipped + c.rows[c.best].degenerate));
  // Per weights, the best boundary of its four rows is the one boundary 'auto' keeps.
  for (WeightKind w : kWeights) {
    const Comparison one = compareParameterizations(mesh, std::nullopt, kKinds, {w}).value();
    ParamOptions options;
    options.boundary = std::nullopt;
    options.weights = w;
    EXPECT_EQ(one.rows[one.best].boundary, parameterize(mesh, options).value().boundary) << weightKindName(w);
  }
}

TEST(CompareParameterizations, AFailedCellKeepsItsErrorAndIsNeverBest) {
  const TriMesh mesh = makeSample("cap").value();
  const SurfacePoint onBoundary = SurfacePoint::vertex(mesh.boundaryLoops()[0][0]);
  const Comparison c = compareParameterizations(mesh, onBoundary, kKinds, {WeightKind::Uniform}).value();
  ASSERT_EQ(c.rows.size(), 4u);
  ASSERT_TRUE(c.rows[0].error);
  EXPECT_EQ(c.rows[0].error->code, ErrorCode::InvalidArgument);
  EXPECT_FALSE(c.rows[1].error);
  ASSERT_TRUE(c.rows[3].error);  // free needs an interior source as measured does
  EXPECT_EQ(c.rows[3].error->message, c.rows[0].error->message);
  EXPECT_TRUE(c.best == 1 || c.best == 2);
}

TEST(CompareParameterizations, AFreeRowAloneOrListedFirstIsTheSameRefinement) {
  const TriMesh mesh = makeSample("mountain").value();
  const std::vector<WeightKind> weights = {WeightKind::MeanValue, WeightKind::Uniform};
  const Comparison alone = compareParameterizations(mesh, std::nullopt, {BoundaryKind::Free}, weights).value();
  const Comparison first =
      compareParameterizations(mesh, std::nullopt, {BoundaryKind::Free, BoundaryKind::Measured}, weights).value();
  ASSERT_EQ(alone.rows.size(), 2u);
  ASSERT_EQ(first.rows.size(), 4u);
  for (size_t w = 0; w < weights.size(); ++w) {
    const ComparisonRow &a = alone.rows[w], &f = first.rows[w];
    ASSERT_FALSE(a.error);
    EXPECT_EQ(a.boundary, BoundaryKind::Free);
    EXPECT_EQ(f.boundary, BoundaryKind::Free);
    EXPECT_EQ(a.weights, weights[w]);
    EXPECT_EQ(f.weights, weights[w]);
    EXPECT_EQ(a.l2, f.l2);
    EXPECT_EQ(a.init, f.init);
    EXPECT_GT(a.timeMs, 0);  // the start's solve is part of it
    EXPECT_EQ(first.rows[2 + w].boundary, BoundaryKind::Measured);
    EXPECT_FALSE(first.rows[2 + w].init);
  }
}

TEST(CompareParameterizations, CutsWhatIsNotADiskAndCancelsAsAnError) {
  // A closed mesh: every cell cuts it the same way, so each row is that cell's parameterization.
  const TriMesh sphere = testing::icosphere(2);
  const auto closed = compareParameterizations(sphere, std::nullopt, {BoundaryKind::Circle}, {WeightKind::Uniform});
  ASSERT_TRUE(closed.ok()) << closed.error().message;
  ParamOptions o;
  o.boundary = BoundaryKind::Circle;
  o.weights = WeightKind::Uniform;
  EXPECT_EQ(closed.value().rows[0].l2, parameterize(sphere, o).value().metrics.l2);
  EXPECT_TRUE(closed.value().rows[0].bijective);
  const TriMesh mesh = makeSample("mountain").value();
  int calls = 0;
  const auto stopped = compareParameterizations(mesh, std::nullopt, kKinds, kWeights, LinearSolver::Multigrid,
                                                [&](const char* stage, double) {
                                                  EXPECT_STREQ(stage, "compare");
                                                  return ++calls < 3;
                                                });
  ASSERT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace straightest
