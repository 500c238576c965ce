// Boundary polygons without a solve: the same polygon, in the same [0, 1]² frame, as the
// parameterization with that boundary.
#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"
#include "straightest/param/boundary_polygons.hpp"
#include "straightest/param/parameterize.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

const std::vector<BoundaryKind> kAllKinds = {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square};

TEST(BoundaryPolygons, AreTheParameterizationsPolygonsInItsFrameOnEverySampleDiskOrNot) {
  // A sample that is not a disk is cut (or filled) the same way by both: the polygons are the cut disk's.
  for (const std::string& name : sampleNames()) {
    const TriMesh mesh = makeSample(name).value();
    auto polygons = boundaryPolygons(mesh, std::nullopt, kAllKinds);
    ASSERT_TRUE(polygons.ok()) << name << ": " << polygons.error().message;
    ASSERT_EQ(polygons.value().size(), kAllKinds.size());
    for (const BoundaryPolygon& entry : polygons.value()) {
      ASSERT_FALSE(entry.error) << name << " " << boundaryKindName(entry.kind) << ": " << entry.error->message;
      ParamOptions options;
      options.boundary = entry.kind;
      const Parameterization p = parameterize(mesh, options).value();
      EXPECT_EQ(entry.loop, p.boundaryLoop) << name;
      ASSERT_EQ(entry.polygon.size(), p.boundaryPolygon.size()) << name;
      double lo = 1, hi = 0;
      for (size_t i = 0; i < entry.polygon.size(); ++i) {
        // The interior lies inside the convex polygon, so the uv box is the polygon's box.
        EXPECT_NEAR(entry.polygon[i].x, p.boundaryPolygon[i].x, 1e-12) << name << " " << boundaryKindName(entry.kind);
        EXPECT_NEAR(entry.polygon[i].y, p.boundaryPolygon[i].y, 1e-12) << name << " " << boundaryKindName(entry.kind);
        lo = std::min({lo, entry.polygon[i].x, entry.polygon[i].y});
        hi = std::max({hi, entry.polygon[i].x, entry.polygon[i].y});
      }
      EXPECT_EQ(lo, 0.0) << "the box touches the frame's lower sides";
      EXPECT_EQ(hi, 1.0) << "the longer side spans [0, 1]";
    }
  }
}

TEST(BoundaryPolygons, AMeasuredBoundaryWithABoundarySourceFailsAloneWithTheParameterizationsError) {
  const TriMesh mesh = makeSample("cap").value();
  const SurfacePoint onBoundary = SurfacePoint::vertex(mesh.boundaryLoops()[0][0]);
  const auto polygons = boundaryPolygons(mesh, onBoundary, kAllKinds).value();
  ASSERT_TRUE(polygons[0].error);
  EXPECT_EQ(polygons[0].error->code, ErrorCode::InvalidArgument);
  EXPECT_TRUE(polygons[0].polygon.empty());
  ParamOptions options;
  options.source = onBoundary;
  EXPECT_EQ(parameterize(mesh, options).error().message, polygons[0].error->message);
  EXPECT_FALSE(polygons[1].error);
  EXPECT_FALSE(polygons[2].error);
}

TEST(BoundaryPolygons, TheFreeBoundaryHasNoneWithoutItsRefinementAndIsNotADefaultKind) {
  EXPECT_EQ(polygonBoundaryKinds(), kAllKinds);
  const TriMesh mesh = makeSample("cap").value();
  const auto free = boundaryPolygons(mesh, std::nullopt, {BoundaryKind::Circle, BoundaryKind::Free});
  ASSERT_FALSE(free.ok());
  EXPECT_EQ(free.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(free.error().message.find("free boundary has no polygon"), std::string::npos) << free.error().message;
  EXPECT_NE(free.error().message.find("measured, circle and square"), std::string::npos) << free.error().message;
}

TEST(BoundaryPolygons, OnAClosedMeshAreTheCutDisksLoopInMeshNumbersAndStopWhenCancelled) {
  const TriMesh sphere = testing::icosphere(2);
  const auto closed = boundaryPolygons(sphere, std::nullopt, {BoundaryKind::Circle});
  ASSERT_TRUE(closed.ok()) << closed.error().message;
  ParamOptions circle;
  circle.boundary = BoundaryKind::Circle;
  EXPECT_EQ(closed.value()[0].loop, parameterize(sphere, circle).value().boundaryLoop);
  for (int32_t v : closed.value()[0].loop) EXPECT_LT(v, sphere.numVertices());
  const TriMesh mesh = makeSample("mountain").value();
  const auto cancelled = boundaryPolygons(mesh, std::nullopt, {BoundaryKind::Measured},
                                          [](const char*, double) { return false; });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

}  // namespace
}  // namespace straightest
