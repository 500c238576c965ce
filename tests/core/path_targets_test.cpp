// Batch targets and what a batch reports: 'boundary' expanded in the core, each path's in-plane
// direction (the cutting plane the page draws), the summary, and cancellation as an error.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

TEST(ResolveTargets, ExpandsBoundaryEntriesInPlaceAndNamesTheBadTarget) {
  const TriMesh mesh = makeSample("mountain").value();
  const std::vector<SurfacePoint> boundary = boundaryTargets(mesh);
  ASSERT_FALSE(boundary.empty());
  const auto targets =
      resolveTargets(mesh, {SurfacePoint::vertex(3), BoundaryVertices{}, SurfacePoint::vertex(5)}).value();
  ASSERT_EQ(targets.size(), boundary.size() + 2);
  EXPECT_EQ(targets.front().index, 3);
  EXPECT_EQ(targets.back().index, 5);
  for (size_t i = 0; i < boundary.size(); ++i) EXPECT_EQ(targets[i + 1].index, boundary[i].index);
  EXPECT_EQ(boundary.size(), mesh.boundaryLoops()[0].size());

  const auto bad = resolveTargets(mesh, {SurfacePoint::vertex(0), SurfacePoint::vertex(mesh.numVertices())});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message.rfind("target 1: ", 0), 0u) << bad.error().message;

  for (const TargetSpec& spec : {TargetSpec{BoundaryVertices{}}, TargetSpec{AllBoundaryVertices{}}}) {
    const auto closed = resolveTargets(testing::icosphere(1), {SurfacePoint::vertex(2), spec});
    ASSERT_FALSE(closed.ok());
    EXPECT_EQ(closed.error().code, ErrorCode::Topology);
    EXPECT_NE(closed.error().message.find("closed"), std::string::npos) << closed.error().message;
    EXPECT_NE(closed.error().message.find("name the targets"), std::string::npos) << closed.error().message;
  }
}

TEST(ResolveTargets, AllBoundariesGivesEveryLoopsVerticesInOrderLongestLoopFirst) {
  // An 8 × 8-cell grid with a 1-cell hole (4 boundary vertices) and a 2-cell hole (6): three loops.
  const TriMesh mesh = testing::gridWithout({{2, 2}, {5, 4}, {5, 5}});
  ASSERT_EQ(mesh.boundaryLoops().size(), 3u);
  const auto targets = resolveTargets(mesh, {AllBoundaryVertices{}, SurfacePoint::vertex(40)}).value();
  std::vector<int32_t> expected;
  size_t previous = std::numeric_limits<size_t>::max();
  for (const auto& loop : mesh.boundaryLoops()) {
    EXPECT_LE(loop.size(), previous);  // longest first
    previous = loop.size();
    expected.insert(expected.end(), loop.begin(), loop.end());
  }
  EXPECT_EQ(mesh.boundaryLoops()[0].size(), 32u);  // the outer square
  EXPECT_EQ(mesh.boundaryLoops()[1].size(), 6u);
  EXPECT_EQ(mesh.boundaryLoops()[2].size(), 4u);
  ASSERT_EQ(targets.size(), expected.size() + 1);
  std::vector<int32_t> boundaryVertices;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (mesh.isBoundaryVertex(v)) boundaryVertices.push_back(v);
  std::vector<int32_t> got;
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(targets[i].kind, SurfacePoint::Kind::Vertex);
    EXPECT_EQ(targets[i].index, expected[i]);
    got.push_back(targets[i].index);
  }
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, boundaryVertices);  // every boundary vertex exactly once
  EXPECT_EQ(targets.back().index, 40);
  // 'boundary' is the first loop alone.
  EXPECT_EQ(resolveTargets(mesh, {BoundaryVertices{}}).value().size(), 32u);
}

TEST(TraceStraightestPaths, AClosedMeshWithExplicitTargetsReportsItsBaseNormalFallback) {
  // No boundary loop, so no virtual faces: the base normal is the area-weighted normal, and the batch says so.
  const TriMesh mesh = testing::icosphere(1);
  const PathBatch batch = traceStraightestPaths(mesh, SurfacePoint::vertex(0),
                                                {SurfacePoint::vertex(3), SurfacePoint::vertex(7)}, TraceOptions{false})
                              .value();
  EXPECT_TRUE(batch.base.fallback);
  EXPECT_NE(batch.base.note.find("closed"), std::string::npos) << batch.base.note;
  EXPECT_NE(batch.base.note.find("area-weighted normal"), std::string::npos) << batch.base.note;
  EXPECT_EQ(batch.status.size(), 2u);
}

TEST(TraceStraightestPaths, DirectionsSpanTheCuttingPlaneWithTheBaseNormal) {
  const TriMesh mesh = makeSample("saddle").value();
  const SurfacePoint source = resolveSource(mesh, std::nullopt).value();
  std::vector<SurfacePoint> targets = boundaryTargets(mesh);
  targets.push_back(source);  // D == S: no plane
  const PathBatch batch = traceStraightestPaths(mesh, source, targets, TraceOptions{false}).value();
  ASSERT_EQ(batch.directions.size(), targets.size());
  ASSERT_EQ(batch.targetPositions.size(), targets.size());
  const Vec3 n = batch.base.normal;
  for (size_t i = 0; i + 1 < targets.size(); ++i) {
    const Vec3 t = batch.directions[i];
    const Vec3 SD = batch.targetPositions[i] - batch.base.origin;
    EXPECT_EQ(norm(batch.targetPositions[i] - position(mesh, targets[i])), 0.0);
    EXPECT_NEAR(norm(t), 1, 1e-12);
    EXPECT_NEAR(dot(t, n), 0, 1e-12);                        // in the base plane
    EXPECT_GT(dot(t, SD), 0);                                // toward D
    EXPECT_NEAR(dot(SD, cross(t, n)), 0, 1e-12 * norm(SD));  // D lies in the plane spanned by t and n
    // ... which is the cutting plane the walk follows.
    const CuttingPlane plane = cuttingPlane(batch.base, batch.targetPositions[i]).value();
    EXPECT_NEAR(std::abs(dot(plane.normal, cross(t, n))), 1, 1e-9);
  }
  EXPECT_TRUE(std::isnan(batch.directions.back().x) && std::isnan(batch.directions.back().y) &&
              std::isnan(batch.directions.back().z));
  EXPECT_EQ(batch.status.back(), TraceStatus::Reached);  // at the source: reached with length 0
}

TEST(Summarize, CountsEveryStatusOnceAndAveragesTheReachedLengths) {
  const TriMesh mesh = testing::lShape(6);                    // [0, 12]² without (6, 12]²
  const SurfacePoint source = SurfacePoint::vertex(13 + 11);  // (11, 1), at the end of one arm
  const PathBatch batch = traceStraightestPaths(mesh, source, boundaryTargets(mesh), TraceOptions{false}).value();
  const PathSummary s = summarize(batch);
  EXPECT_EQ(s.paths, static_cast<int64_t>(batch.status.size()));
  int64_t total = 0, crossed = 0, mostCrossed = 0;
  for (int64_t c : s.byStatus) total += c;
  EXPECT_EQ(total, s.paths);
  double sum = 0, longest = 0;
  int64_t reached = 0;
  for (size_t i = 0; i < batch.status.size(); ++i) {
    crossed += batch.facesCrossed[i];
    mostCrossed = std::max(mostCrossed, batch.facesCrossed[i]);
    if (batch.status[i] != TraceStatus::Reached) continue;
    ++reached;
    sum += batch.length[i];
    longest = std::max(longest, batch.length[i]);
  }
  EXPECT_EQ(s.reached, reached);
  EXPECT_EQ(s.byStatus[0], reached);
  EXPECT_LT(s.reached, s.paths) << "the L-shape's reentrant corner hides some targets";
  EXPECT_NEAR(s.meanLength, sum / reached, 1e-12);
  EXPECT_EQ(s.maxLength, longest);
  EXPECT_EQ(s.facesCrossed, crossed);
  EXPECT_EQ(s.maxFacesCrossed, mostCrossed);
  EXPECT_GT(s.maxFacesCrossed, 0);
}

TEST(TraceStraightestPaths, RecordsItsStagesInTheGivenTimings) {
  const TriMesh mesh = makeSample("cap").value();
  Timings timings;
  traceStraightestPaths(mesh, SurfacePoint::vertex(defaultSource(mesh).value()), boundaryTargets(mesh),
                        TraceOptions{false, 0, &timings})
      .value();
  ASSERT_EQ(timings.stages().size(), 2u);
  EXPECT_EQ(timings.stages()[0].first, "prepare");
  EXPECT_EQ(timings.stages()[1].first, "trace");
  EXPECT_GE(timings["trace"], 0);
  EXPECT_EQ(timings["never recorded"], 0);
}

}  // namespace
}  // namespace straightest
