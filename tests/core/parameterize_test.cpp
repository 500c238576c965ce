// Measured-boundary parameterization and texture stretch: facts a flattening must satisfy.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "straightest/base/threads.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::GridPattern;

Parameterization param(const TriMesh& mesh, std::optional<BoundaryKind> b, WeightKind w) {
  ParamOptions o;
  o.boundary = b;
  o.weights = w;
  auto r = parameterize(mesh, o);
  if (!r) ADD_FAILURE() << r.error().message;
  return std::move(r).value();
}

/// uv is a similarity image of the flat mesh: every edge scaled by one factor, orientation kept.
void expectSimilarity(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  const Triangle& t0 = mesh.triangle(0);
  const double k = std::hypot(uv[t0[1]][0] - uv[t0[0]][0], uv[t0[1]][1] - uv[t0[0]][1]) /
                   norm(mesh.position(t0[1]) - mesh.position(t0[0]));
  for (const Triangle& t : mesh.triangles())
    for (int c = 0; c < 3; ++c) {
      const int32_t i = t[c], j = t[(c + 1) % 3];
      const double d2 = std::hypot(uv[j][0] - uv[i][0], uv[j][1] - uv[i][1]);
      ASSERT_NEAR(d2, k * norm(mesh.position(j) - mesh.position(i)), 1e-9 * k) << "edge " << i << "-" << j;
    }
}

TEST(MeasuredBoundary, PlanarConvexPatchReproducesItselfWithEveryConvexCombination) {
  const TriMesh mesh = testing::flatGrid(15, GridPattern::Jittered);
  for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Cotan}) {
    const Parameterization p = param(mesh, BoundaryKind::Measured, w);
    EXPECT_NEAR(p.metrics.l2, 1, 1e-9) << weightKindName(w);
    EXPECT_NEAR(p.metrics.linf, 1, 1e-9) << weightKindName(w);
    EXPECT_EQ(p.fallbacks, 0);
    expectSimilarity(mesh, p.uv);
    for (const Vec2& q : p.uv) {  // scaled into [0, 1]² keeping the aspect ratio
      EXPECT_GE(q[0], -1e-12);
      EXPECT_LE(q[1], 1 + 1e-12);
    }
  }
}

/// A disk whose vertices all lie on its boundary (a lone triangle, a strip of quads, CGAL's quad.off) has
/// no vertex for the default source: the middle of its largest face is the source, and a flat strip
/// still maps onto itself.
TEST(MeasuredBoundary, AStripWithEveryVertexOnTheBoundaryMapsOntoItselfFromItsLargestFacesMiddle) {
  // Two quads side by side (4 triangles) with the last one the largest, and a lone triangle.
  const TriMesh strip = testing::buildOrFail({{0, 0, 0}, {1, 0, 0}, {2.5, 0, 0}, {0, 1, 0}, {1, 1.2, 0}, {2.5, 1.1, 0}},
                                             {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}});
  const TriMesh triangle = testing::buildOrFail({{0, 0, 0}, {2, 0, 0}, {0.5, 1.5, 0}}, {{0, 1, 2}});
  for (const TriMesh* mesh : {&strip, &triangle}) {
    EXPECT_FALSE(defaultSource(*mesh).ok());  // no interior vertex
    const auto source = resolveSource(*mesh, std::nullopt);
    ASSERT_TRUE(source) << source.error().message;
    EXPECT_EQ(source.value().kind, SurfacePoint::Kind::Face);
    int32_t largest = 0;
    for (int32_t f = 1; f < mesh->numFaces(); ++f)
      if (mesh->faceArea(f) > mesh->faceArea(largest)) largest = f;
    EXPECT_EQ(source.value().index, largest);
    for (auto kind : {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Free}) {
      const Parameterization p = param(*mesh, kind, WeightKind::ShapePreserving);
      EXPECT_TRUE(p.metrics.bijective) << boundaryKindName(kind);
      if (kind == BoundaryKind::Measured) expectSimilarity(*mesh, p.uv);  // a flat disk measured from inside
    }
  }
  // But a triangle soup (faces sharing no vertices) is refused, not mapped one triangle of many.
  const TriMesh soup = testing::buildOrFail({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}},
                                            {{0, 1, 2}, {3, 4, 5}});
  const auto refused = parameterize(soup, ParamOptions{});
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, ErrorCode::Topology) << refused.error().message;
}

TEST(MeasuredBoundary, DevelopableCylinderPatchIsNearlyIsometric) {
  const double R = 1.0;
  const int n = 41;
  const TriMesh mesh = testing::grid(n, GridPattern::UnionJack, [&](double i, double j) {
    const double theta = -1.2 + 2.4 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
    return Vec3{R * std::sin(theta), y, R * std::cos(theta)};
  });
  const Parameterization measured = param(mesh, BoundaryKind::Measured, WeightKind::ShapePreserving);
  const Parameterization circle = param(mesh, BoundaryKind::Circle, WeightKind::ShapePreserving);
  EXPECT_LT(measured.metrics.l2, 1.01);
  EXPECT_GT(circle.metrics.l2, measured.metrics.l2);
}

TEST(Parameterize, ConvexBoundaryWithConvexWeightsNeverFlipsOnTheSamples) {
  for (const std::string& name : sampleNames()) {
    const TriMesh mesh = makeSample(name).value();
    for (BoundaryKind b : {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square})
      for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Uniform}) {
        const Parameterization p = param(mesh, b, w);
        EXPECT_EQ(p.metrics.flipped, 0) << name << " " << boundaryKindName(p.boundary) << " " << weightKindName(w);
        EXPECT_EQ(p.metrics.degenerate, 0) << name << " " << boundaryKindName(p.boundary) << " " << weightKindName(w);
        EXPECT_TRUE(std::isfinite(p.metrics.l2));
        EXPECT_LT(p.residual, 1e-9);
      }
  }
}

TEST(Parameterize, AutoKeepsTheLeastStretchedCandidate) {
  const TriMesh mesh = makeSample("mountain").value();
  const Parameterization p = param(mesh, std::nullopt, WeightKind::ShapePreserving);
  ASSERT_EQ(p.candidates.size(), 4u);
  for (const BoundaryCandidate& c : p.candidates) EXPECT_LE(p.metrics.l2, c.l2);
}

TEST(Parameterize, RequireDiskSaysWhatWasFoundAndParameterizeCutsOrFillsWhatIsNotADisk) {
  const TriMesh tetrahedron = testing::loadGood("good/tetrahedron.off");
  const TriMesh annulus = testing::loadGood("good/annulus.off");
  auto closed = requireDisk(tetrahedron);
  ASSERT_FALSE(closed.ok());
  EXPECT_EQ(closed.error().code, ErrorCode::Topology);
  EXPECT_NE(closed.error().message.find("closed"), std::string::npos) << closed.error().message;
  auto holed = requireDisk(annulus);
  ASSERT_FALSE(holed.ok());
  EXPECT_NE(holed.error().message.find("2 boundary loops"), std::string::npos) << holed.error().message;
  // parameterize makes them disks (parameterize_cut_test.cpp has the geometry) and says how.
  const Parameterization cut = param(tetrahedron, BoundaryKind::Circle, WeightKind::ShapePreserving);
  EXPECT_EQ(cut.cut, CutMethod::Path);
  EXPECT_FALSE(cut.seam.empty());
  EXPECT_TRUE(cut.metrics.bijective);
  const Parameterization filled = param(annulus, BoundaryKind::Circle, WeightKind::ShapePreserving);
  EXPECT_EQ(filled.cut, CutMethod::Fill);
  EXPECT_EQ(filled.filledLoops.size(), 1u);
  EXPECT_TRUE(filled.metrics.bijective);
  // A disk says it is one, with its corners the vertex map.
  const TriMesh disk = makeSample("cap").value();
  const Parameterization p = param(disk, BoundaryKind::Circle, WeightKind::ShapePreserving);
  EXPECT_EQ(p.cut, CutMethod::Disk);
  EXPECT_TRUE(p.seam.empty() && p.filledLoops.empty());
  EXPECT_EQ(p.virtualVertices, 0);
  ASSERT_EQ(p.cornerUv.size(), 3 * static_cast<size_t>(disk.numFaces()));
  for (int32_t f = 0; f < disk.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(p.cornerUv[3 * f + k], p.uv[disk.triangle(f)[k]]);
}

TEST(Parameterize, RefusesASourceOnTheBoundaryOrOutOfRange) {
  const TriMesh mesh = makeSample("cap").value();
  ParamOptions o;
  o.source = SurfacePoint::vertex(mesh.boundaryLoops()[0][0]);
  auto onBoundary = parameterize(mesh, o);
  ASSERT_FALSE(onBoundary.ok());
  EXPECT_NE(onBoundary.error().message.find("on the boundary"), std::string::npos);
  o.source = SurfacePoint::vertex(mesh.numVertices());
  EXPECT_FALSE(parameterize(mesh, o).ok());
  EXPECT_FALSE(parseBoundaryChoice("ellipse").ok());
  EXPECT_FALSE(parseWeightKind("harmonic").ok());
}

TEST(Parameterize, RefusesASourceWithinSnappingDistanceOfTheBoundary) {
  // The tracer moves a source within 1e-6 of a vertex onto it; a point 2e-8 from a boundary vertex
  // became a boundary source with radius 0 (found by fuzzing). It must be refused like a boundary vertex.
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  const int32_t h = testing::findHalfedge(mesh, 1, 6);  // interior, from boundary vertex (1, 0) to (1, 1)
  ASSERT_GE(h, 0);
  ParamOptions options;
  options.source = SurfacePoint::edge(h, 2e-8);
  auto p = parameterize(mesh, options);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(p.error().message.find("on the boundary"), std::string::npos) << p.error().message;
  options.source = SurfacePoint::edge(h, 0.5);  // well inside: fine
  EXPECT_TRUE(parameterize(mesh, options).ok());
}

TEST(Parameterize, IsScaleInvariant) {
  const TriMesh base = makeSample("face").value();
  const Parameterization reference = parameterize(base, {}).value();
  for (double s : {1e-6, 1e6}) {
    const Parameterization p = parameterize(testing::scaled(base, s), {}).value();
    EXPECT_NEAR(p.metrics.l2, reference.metrics.l2, 1e-9) << "scale " << s;
    EXPECT_NEAR(p.metrics.linf, reference.metrics.linf, 1e-7) << "scale " << s;
    ASSERT_EQ(p.uv.size(), reference.uv.size());
    for (size_t v = 0; v < p.uv.size(); v += 17) {
      EXPECT_NEAR(p.uv[v][0], reference.uv[v][0], 1e-9);
      EXPECT_NEAR(p.uv[v][1], reference.uv[v][1], 1e-9);
    }
  }
}

TEST(Parameterize, AlmostFlatPatchIsNearlyAnIsometry) {
  const Parameterization p = parameterize(testing::almostFlatGrid(21, 1e-10), {}).value();
  EXPECT_NEAR(p.metrics.l2, 1.0, 1e-6);
  EXPECT_TRUE(p.metrics.bijective);
}

TEST(Parameterize, AlmostClosedCapIsBijectiveOnACircleAndMeasuredGivesAResultOrAClearError) {
  // A sphere with a small hole at the bottom: the base normal at the pole is the fallback (base_plane_test).
  const TriMesh mesh = makeSphericalCap(1.0, testing::kPi - 0.05, 24);
  ParamOptions o;
  o.boundary = BoundaryKind::Circle;
  const Parameterization p = parameterize(mesh, o).value();
  EXPECT_TRUE(p.metrics.bijective);  // Tutte: a convex boundary and convex weights never fold
  o.boundary = BoundaryKind::Measured;
  auto measured = parameterize(mesh, o);  // may be poor, but it is a result or a clear error
  if (measured) {
    EXPECT_EQ(std::isfinite(measured.value().metrics.l2), measured.value().metrics.bijective);
  } else {
    EXPECT_FALSE(measured.error().message.empty());
  }
}

// The free boundary. These hold for any correct refinement: they specify the plumbing (the start rule,
// the fields, the candidates, errors, cancellation), not how far the energy goes down.

/// What every free result must satisfy: a map in [0, 1]² whose polygon is its loop's uv, honest
/// bijectivity, the refinement's fields, and itself as the last candidate.
void expectFreeResult(const TriMesh& mesh, const Parameterization& p, const ParamOptions& o) {
  EXPECT_EQ(p.boundary, BoundaryKind::Free);
  ASSERT_TRUE(p.init);
  EXPECT_TRUE(*p.init == BoundaryKind::Measured || *p.init == BoundaryKind::Circle);
  EXPECT_GE(p.iterations, 0);
  EXPECT_LE(p.iterations, o.free.maxIterations);
  const StretchMetrics& m = p.metrics;
  EXPECT_EQ(m.bijective, m.flipped == 0 && m.degenerate == 0 && m.overlaps == 0);
  EXPECT_EQ(std::isfinite(m.l2), m.bijective);
  ASSERT_EQ(p.uv.size(), static_cast<size_t>(mesh.numVertices()));
  for (const Vec2& q : p.uv) {
    EXPECT_TRUE(q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= 1) << q.x << ", " << q.y;
  }
  ASSERT_EQ(p.boundaryPolygon.size(), p.boundaryLoop.size());
  if (p.cut == CutMethod::Disk) {
    EXPECT_EQ(p.boundaryLoop, mesh.boundaryLoops()[0]);
    for (size_t i = 0; i < p.boundaryLoop.size(); ++i) {
      EXPECT_EQ(p.boundaryPolygon[i].x, p.uv[p.boundaryLoop[i]].x);
      EXPECT_EQ(p.boundaryPolygon[i].y, p.uv[p.boundaryLoop[i]].y);
    }
  } else {
    // Cut or filled: the loop is the disk's, in mesh numbers; a seam vertex has a uv per side, and the
    // polygon's point is the uv of one of its corners.
    std::vector<std::vector<Vec2>> cornersOf(mesh.numVertices());
    for (int32_t f = 0; f < mesh.numFaces(); ++f)
      for (int k = 0; k < 3; ++k) cornersOf[mesh.triangle(f)[k]].push_back(p.cornerUv[3 * f + k]);
    for (size_t i = 0; i < p.boundaryLoop.size(); ++i) {
      const auto& corners = cornersOf[p.boundaryLoop[i]];
      EXPECT_NE(std::find(corners.begin(), corners.end(), p.boundaryPolygon[i]), corners.end()) << i;
    }
  }
  ASSERT_FALSE(p.candidates.empty());
  const BoundaryCandidate& last = p.candidates.back();
  EXPECT_EQ(last.kind, BoundaryKind::Free);
  EXPECT_EQ(last.l2, m.l2);
  EXPECT_EQ(last.flipped, m.flipped);
  EXPECT_EQ(last.overlaps, m.overlaps);
}

TEST(FreeBoundary, StartsFromTheMeasuredMapWhereItIsBijectiveElseFromTheCircle) {
  for (const std::string& name : sampleNames())
    for (WeightKind w : {WeightKind::ShapePreserving, WeightKind::Cotan}) {
      const TriMesh mesh = makeSample(name).value();
      ParamOptions o;
      o.weights = w;
      o.free.maxIterations = 20;
      o.boundary = BoundaryKind::Measured;
      auto measured = parameterize(mesh, o);
      o.boundary = BoundaryKind::Free;
      const Parameterization p = parameterize(mesh, o).value();
      expectFreeResult(mesh, p, o);
      const bool measuredStarts = measured && measured.value().metrics.bijective;
      EXPECT_EQ(*p.init, measuredStarts ? BoundaryKind::Measured : BoundaryKind::Circle) << name;
      // Its candidates are the maps it solved: measured, the circle only when measured would not do, itself.
      std::vector<BoundaryKind> solved;
      for (const BoundaryCandidate& c : p.candidates) solved.push_back(c.kind);
      if (measuredStarts) {
        EXPECT_EQ(solved, (std::vector<BoundaryKind>{BoundaryKind::Measured, BoundaryKind::Free})) << name;
        EXPECT_EQ(p.fallbacks, measured.value().fallbacks);
        if (std::isfinite(p.energyInitial)) {
          EXPECT_LE(p.energyFinal, p.energyInitial) << name;
        }
      } else {
        EXPECT_EQ(solved.back(), BoundaryKind::Free);
        EXPECT_EQ(solved[solved.size() - 2], BoundaryKind::Circle);
      }
    }
}

TEST(FreeBoundary, IsRefinedFromTheFixedMapExactlyAsRefineParameterizationDoes) {
  const TriMesh mesh = makeSample("face").value();
  ParamOptions o;
  o.free.maxIterations = 15;
  const Parameterization measured = parameterize(mesh, o).value();
  ASSERT_TRUE(measured.metrics.bijective);
  o.boundary = BoundaryKind::Free;
  const Parameterization free = parameterize(mesh, o).value();
  const Parameterization refined = refineParameterization(mesh, measured, o.free).value();
  EXPECT_EQ(refined.init, BoundaryKind::Measured);
  ASSERT_EQ(refined.uv.size(), free.uv.size());
  for (size_t v = 0; v < free.uv.size(); ++v) {
    EXPECT_EQ(refined.uv[v].x, free.uv[v].x);
    EXPECT_EQ(refined.uv[v].y, free.uv[v].y);
  }
  EXPECT_EQ(refined.metrics.l2, free.metrics.l2);
  EXPECT_EQ(refined.iterations, free.iterations);
  // A free map is not a start; nor is a uv of the wrong size.
  EXPECT_EQ(refineParameterization(mesh, free).error().code, ErrorCode::InvalidArgument);
  Parameterization shortStart = measured;
  shortStart.uv.pop_back();
  EXPECT_EQ(refineParameterization(mesh, shortStart).error().code, ErrorCode::InvalidArgument);
  EXPECT_EQ(refineParameterization(testing::icosphere(1), measured).error().code, ErrorCode::Topology);
}

TEST(FreeBoundary, AutoRefinesWhatItSolvedAndKeepsThePreferredOfFour) {
  for (const char* name : {"mountain", "cap"}) {
    const TriMesh mesh = makeSample(name).value();
    ParamOptions o;
    o.boundary = std::nullopt;
    o.free.maxIterations = 10;
    const Parameterization p = parameterize(mesh, o).value();
    ASSERT_EQ(p.candidates.size(), 4u) << name;
    const BoundaryKind order[] = {BoundaryKind::Measured, BoundaryKind::Circle, BoundaryKind::Square,
                                  BoundaryKind::Free};
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(p.candidates[i].kind, order[i]) << name;
    // The free candidate is boundary free's map: the same start, refined the same way.
    o.boundary = BoundaryKind::Free;
    const Parameterization free = parameterize(mesh, o).value();
    EXPECT_EQ(p.candidates[3].l2, free.metrics.l2) << name;
    EXPECT_EQ(p.candidates[3].flipped, free.metrics.flipped) << name;
    // The kept map is the first preferred one in candidate order; its refinement fields only if free.
    size_t best = 0;
    for (size_t i = 1; i < 4; ++i) {
      const BoundaryCandidate &c = p.candidates[i], &b = p.candidates[best];
      if (preferredMap(c.l2, c.flipped + c.degenerate, b.l2, b.flipped + b.degenerate)) best = i;
    }
    EXPECT_EQ(p.boundary, p.candidates[best].kind) << name;
    EXPECT_EQ(p.metrics.l2, p.candidates[best].l2) << name;
    EXPECT_EQ(p.init.has_value(), p.boundary == BoundaryKind::Free) << name;
  }
}

TEST(FreeBoundary, OnEverySampleItIsBijectiveAndLessStretchedThanEveryFixedBoundarySoAutoPicksIt) {
  // The samples are curved disks: no fixed convex boundary is an isometry's, and the energy the free
  // boundary lowers bounds the stretch; a bijective start can only give a bijective free map.
  for (const std::string& name : sampleNames()) {
    const TriMesh mesh = makeSample(name).value();
    ParamOptions o;
    o.boundary = std::nullopt;
    const Parameterization p = parameterize(mesh, o).value();
    ASSERT_EQ(p.candidates.size(), 4u) << name;
    const BoundaryCandidate& free = p.candidates[3];
    ASSERT_EQ(free.kind, BoundaryKind::Free) << name;
    EXPECT_TRUE(std::isfinite(free.l2)) << name;
    EXPECT_EQ(free.flipped + free.degenerate + free.overlaps, 0) << name;
    for (size_t i = 0; i < 3; ++i) EXPECT_LT(free.l2, p.candidates[i].l2) << name << " vs " << i;
    EXPECT_GT(free.l2, 1) << name;
    EXPECT_EQ(p.boundary, BoundaryKind::Free) << name;
    EXPECT_TRUE(p.converged) << name;
    EXPECT_LT(p.energyFinal, p.energyInitial) << name;
    EXPECT_GE(p.energyFinal, 4) << name;  // 4 per unit area only for an isometry
  }
}

TEST(FreeBoundary, TimingsListRefineAndOnlyFreeAndAutoSpendTimeThere) {
  const TriMesh mesh = makeSample("mountain").value();
  const std::vector<std::string> stages = {"cut",   "source", "trace",   "boundary", "weights",
                                           "solve", "refine", "metrics", "total"};
  for (std::optional<BoundaryKind> b :
       {std::optional<BoundaryKind>(BoundaryKind::Circle), std::optional<BoundaryKind>(BoundaryKind::Free),
        std::optional<BoundaryKind>()}) {
    Timings timings;
    ParamOptions o;
    o.boundary = b;
    o.timings = &timings;
    o.free.maxIterations = 5;
    const Parameterization p = parameterize(mesh, o).value();
    std::vector<std::string> names;
    for (const auto& [name, ms] : timings.stages()) names.push_back(name);
    EXPECT_EQ(names, stages);
    if (b == BoundaryKind::Circle) {
      EXPECT_EQ(timings["refine"], 0);
      EXPECT_FALSE(p.init);
    }
  }
}

TEST(FreeBoundary, ReportsRefineAndCancellingThereIsACancelledErrorThatLeavesNothingBroken) {
  const TriMesh mesh = makeHeightField(30);
  for (std::optional<BoundaryKind> b :
       {std::optional<BoundaryKind>(BoundaryKind::Free), std::optional<BoundaryKind>()}) {
    ParamOptions o;
    o.boundary = b;
    o.free.maxIterations = 5;
    std::vector<std::string> stages;
    ASSERT_TRUE(parameterize(mesh, o, [&](const char* stage, double) {
                  if (stages.empty() || stages.back() != stage) stages.push_back(stage);
                  return true;
                }).ok());
    const auto refine = std::find(stages.begin(), stages.end(), "refine");
    ASSERT_NE(refine, stages.end());
    EXPECT_NE(std::find(refine, stages.end(), "metrics"), stages.end()) << "metrics after the refinement";
    EXPECT_EQ(stages.back(), "metrics");
    auto cancelled = parameterize(mesh, o, [](const char* stage, double) { return std::string(stage) != "refine"; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
    EXPECT_TRUE(parameterize(mesh, o).ok());  // and the next call works
  }
}

TEST(FreeBoundary, NeedsAnInteriorSourceAsMeasuredDoesAndRefinesWhatIsNotADiskToo) {
  ParamOptions o;
  o.boundary = BoundaryKind::Free;
  o.free.maxIterations = 20;
  for (const char* file : {"good/tetrahedron.off", "good/annulus.off"}) {
    const TriMesh notADisk = testing::loadGood(file);
    auto p = parameterize(notADisk, o);
    ASSERT_TRUE(p.ok()) << file << ": " << p.error().message;
    EXPECT_NE(p.value().cut, CutMethod::Disk) << file;
    EXPECT_TRUE(p.value().metrics.bijective) << file;
  }
  const TriMesh mesh = makeSample("cap").value();
  o.source = SurfacePoint::vertex(mesh.boundaryLoops()[0][0]);
  auto onBoundary = parameterize(mesh, o);
  ASSERT_FALSE(onBoundary.ok());
  EXPECT_EQ(onBoundary.error().code, ErrorCode::InvalidArgument);
  o.boundary = BoundaryKind::Measured;
  EXPECT_EQ(onBoundary.error().message, parameterize(mesh, o).error().message);
}

TEST(ObjWriter, WritesOneVtPerVertexInTheInputOrder) {
  const TriMesh mesh = testing::loadGood("good/quad_grid.obj");
  const Parameterization p = param(mesh, BoundaryKind::Circle, WeightKind::Uniform);
  const std::string text = writeObj(mesh, &p.uv);
  auto reread = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(reread.ok()) << reread.error().message;
  EXPECT_EQ(reread.value().positions()[5].x, mesh.positions()[5].x);
  EXPECT_EQ(reread.value().triangles(), mesh.triangles());
  EXPECT_NE(text.find(" 1/1"), std::string::npos);  // faces as v/vt with vt = v
  EXPECT_NE(text.find("\nvt "), std::string::npos);
}

}  // namespace
}  // namespace straightest

namespace straightest {
namespace {

TEST(Progress, ParameterizationReportsEveryStageAndCanBeCancelled) {
  const TriMesh mesh = makeHeightField(60);
  std::vector<std::string> stages;
  double lastSolve = -1;
  bool monotone = true;
  auto r = parameterize(mesh, {}, [&](const char* stage, double fraction) {
    if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    if (std::string(stage) == "solve") {
      monotone = monotone && fraction >= lastSolve;
      lastSolve = fraction;
    }
    return true;
  });
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(monotone);
  EXPECT_EQ(stages.front(), "source");
  EXPECT_EQ(stages.back(), "metrics");
  EXPECT_NE(std::find(stages.begin(), stages.end(), "trace"), stages.end());
  EXPECT_NE(std::find(stages.begin(), stages.end(), "weights"), stages.end());
  for (const char* stop : {"source", "trace", "weights", "solve", "metrics"}) {
    auto cancelled = parameterize(mesh, {}, [&](const char* stage, double) { return std::string(stage) != stop; });
    ASSERT_FALSE(cancelled.ok()) << stop;
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled) << stop;
  }
}

TEST(Progress, CancellingATraceBatchIsACancelledErrorAtTheNextCheck) {
  const TriMesh mesh = makeHeightField(40);
  int calls = 0;
  // One thread: with more, how many checks the calling thread makes depends on how the chunks were
  // shared (threads_test.cpp specifies the threaded cancel).
  setThreadCount(1);
  auto batch = traceStraightestPaths(mesh, SurfacePoint::vertex(defaultSource(mesh).value()), boundaryTargets(mesh),
                                     TraceOptions{false}, [&](const char*, double) { return ++calls < 10; });
  setThreadCount(0);
  ASSERT_FALSE(batch.ok());
  EXPECT_EQ(batch.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 10);  // stopped at the check that said no, not later
}

}  // namespace
}  // namespace straightest
