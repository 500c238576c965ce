// Straightest paths by cutting planes: geometric facts the walk must reproduce.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;
using testing::kPi;

int32_t centerVertex(const TriMesh& mesh) { return defaultSource(mesh).value(); }

/// Every consecutive pair of path points lies in a common face: the walk never jumps.
void expectConsecutivePointsShareAFace(const TriMesh& mesh, const StraightestPath& path) {
  std::vector<int32_t> a, b;
  for (size_t i = 0; i + 1 < path.points.size(); ++i) {
    incidentFaces(mesh, path.points[i], a);
    incidentFaces(mesh, path.points[i + 1], b);
    const bool shared = std::any_of(a.begin(), a.end(),
                                    [&](int32_t f) { return std::find(b.begin(), b.end(), f) != b.end(); });
    ASSERT_TRUE(shared) << "points " << i << " and " << i + 1 << " share no face";
  }
}

/// What every walk satisfies, whatever its status: it starts at the source; each position is its surface
/// point's; consecutive points share a face, one face crossed per segment; the length is the sum of the
/// segments; every point lies on the cutting plane, and there is no plane exactly when the status is
/// degenerate_plane (or the destination shares a face with the source and is joined directly); a reached
/// path ends at the destination and is no shorter than the chord.
void expectWellFormedPath(const TriMesh& mesh, const StraightestPathTracer& tracer, const SurfacePoint& destination,
                          const StraightestPath& path) {
  const double size = mesh.summary().bbox.diagonal();
  const Vec3 S = position(mesh, tracer.source()), D = position(mesh, destination);
  const char* status = traceStatusName(path.status);
  ASSERT_FALSE(path.points.empty()) << status;
  ASSERT_EQ(path.points.size(), path.positions.size()) << status;
  EXPECT_LE(norm(path.positions.front() - S), 1e-12 * size) << status;
  EXPECT_EQ(path.facesCrossed, static_cast<int64_t>(path.points.size()) - 1) << status;
  double sum = 0;
  for (size_t i = 0; i < path.points.size(); ++i) {
    EXPECT_LE(norm(position(mesh, path.points[i]) - path.positions[i]), 1e-9 * size) << status << " point " << i;
    if (i > 0) sum += norm(path.positions[i] - path.positions[i - 1]);
  }
  expectConsecutivePointsShareAFace(mesh, path);
  EXPECT_NEAR(path.length, sum, 1e-9 * (sum + size)) << status;
  const auto plane = cuttingPlane(tracer.base(), D);
  if (path.status == TraceStatus::DegeneratePlane) {
    EXPECT_FALSE(plane.has_value());
    EXPECT_EQ(path.points.size(), 1u);
  } else if (!plane) {
    EXPECT_EQ(path.status, TraceStatus::Reached) << status << " without a cutting plane";
    EXPECT_LE(path.points.size(), 2u) << "a path without a cutting plane";
  } else {
    for (const Vec3& p : path.positions) EXPECT_LE(std::abs(dot(plane->normal, p - S)), 1e-7 * size) << status;
  }
  if (path.status == TraceStatus::Reached) {
    EXPECT_LE(norm(path.positions.back() - D), 1e-9 * size);
    EXPECT_GE(path.length, norm(D - S) * (1 - 1e-12) - 1e-12 * size);
  }
}

/// On a plane, the straightest distance is the Euclidean distance and the path lies on its plane.
void expectEuclideanPaths(const TriMesh& mesh, const SurfacePoint& source, const std::vector<SurfacePoint>& targets) {
  StraightestPathTracer tracer(mesh, source);
  const double size = mesh.summary().bbox.diagonal();
  EXPECT_NEAR(std::abs(tracer.base().normal.z), 1.0, 1e-12);
  for (const SurfacePoint& target : targets) {
    const Vec3 S = position(mesh, source), D = position(mesh, target);
    if (norm(D - S) == 0) continue;
    const StraightestPath& path = tracer.trace(target);
    ASSERT_EQ(path.status, TraceStatus::Reached) << "target at (" << D.x << ", " << D.y << ")";
    EXPECT_NEAR(path.length, norm(D - S), 1e-12 * norm(D - S));
    const auto plane = cuttingPlane(tracer.base(), D).value();
    for (const Vec3& p : path.positions) ASSERT_LE(std::abs(dot(plane.normal, p - S)), 1e-9 * size);
    EXPECT_EQ(path.positions.front().x, S.x);
    EXPECT_EQ(path.positions.back().x, D.x);
    expectConsecutivePointsShareAFace(mesh, path);
  }
}

std::vector<SurfacePoint> randomFacePoints(const TriMesh& mesh, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int32_t> face(0, mesh.numFaces() - 1);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  std::vector<SurfacePoint> points;
  for (int i = 0; i < count; ++i) {
    double a = u(rng), b = u(rng), c = u(rng);
    const double s = a + b + c;
    points.push_back(SurfacePoint::face(face(rng), {a / s, b / s, c / s}));
  }
  return points;
}

TEST(StraightestPathOnAPlane, RegularGridWhereDiagonalPlanesPassThroughVertices) {
  const TriMesh mesh = testing::flatGrid(21, GridPattern::Regular);
  // Boundary targets include exact diagonals (the plane runs through vertices and along edges).
  expectEuclideanPaths(mesh, SurfacePoint::vertex(centerVertex(mesh)), boundaryTargets(mesh));
  std::vector<SurfacePoint> all;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) all.push_back(SurfacePoint::vertex(v));
  expectEuclideanPaths(mesh, SurfacePoint::vertex(0), all);  // from a corner: every edge direction
}

TEST(StraightestPathOnAPlane, JitteredGrid) {
  const TriMesh mesh = testing::flatGrid(25, GridPattern::Jittered);
  expectEuclideanPaths(mesh, SurfacePoint::vertex(centerVertex(mesh)), boundaryTargets(mesh));
}

TEST(StraightestPathOnAPlane, UnionJackGrid) {
  const TriMesh mesh = testing::flatGrid(21, GridPattern::UnionJack);
  expectEuclideanPaths(mesh, SurfacePoint::vertex(centerVertex(mesh)), boundaryTargets(mesh));
}

TEST(StraightestPathOnAPlane, FacePointSourcesAndTargets) {
  const TriMesh mesh = testing::flatGrid(15, GridPattern::Jittered);
  const auto sources = randomFacePoints(mesh, 5, 1);
  for (const auto& s : sources) {
    expectEuclideanPaths(mesh, s, randomFacePoints(mesh, 40, 2));
    expectEuclideanPaths(mesh, s, boundaryTargets(mesh));
  }
}

TEST(StraightestPathOnAPlane, EdgePointsAreValidSourcesAndTargets) {
  const TriMesh mesh = testing::flatGrid(11, GridPattern::UnionJack);
  std::vector<SurfacePoint> targets;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); h += 7) targets.push_back(SurfacePoint::edge(h, 0.3));
  expectEuclideanPaths(mesh, SurfacePoint::edge(100, 0.5), targets);
}

TEST(StraightestPathTracer, ASourceOnEitherHalfedgeOfItsEdgeIsOneSourceWithTheSamePaths) {
  const TriMesh mesh = makeSample("mountain").value();
  int32_t h = -1;  // an interior edge away from the boundary
  for (int32_t k = 0; k < 3 * mesh.numFaces() && h < 0; ++k)
    if (mesh.twin(k) > k && !mesh.isBoundaryVertex(mesh.tail(k)) && !mesh.isBoundaryVertex(mesh.head(k))) h = k;
  ASSERT_GE(h, 0);
  StraightestPathTracer a(mesh, SurfacePoint::edge(h, 0.25)), b(mesh, SurfacePoint::edge(mesh.twin(h), 0.75));
  EXPECT_EQ(a.source(), b.source());
  EXPECT_EQ(a.source(), SurfacePoint::edge(h, 0.25));  // canonical: the smaller halfedge
  const auto targets = boundaryTargets(mesh);
  ASSERT_FALSE(targets.empty());
  for (const SurfacePoint& target : targets) {
    const StraightestPath pa = a.trace(target);  // a copy: the next trace reuses the buffers
    const StraightestPath& pb = b.trace(target);
    EXPECT_EQ(pa.status, pb.status);
    EXPECT_EQ(pa.length, pb.length);
    EXPECT_EQ(pa.points.size(), pb.points.size());
  }
  // A destination given on either halfedge validates to one point and is reached the same way.
  const SurfacePoint d1 = validateSurfacePoint(mesh, SurfacePoint::edge(h, 0.5)).value();
  const SurfacePoint d2 = validateSurfacePoint(mesh, SurfacePoint::edge(mesh.twin(h), 0.5)).value();
  EXPECT_EQ(d1, d2);
}

TEST(StraightestPathOnASphericalCap, LengthConvergesToGreatCircleArcQuadratically) {
  const double thetaMax = kPi / 3;
  double previousError = 0;
  for (int rings : {8, 16, 32}) {
    const TriMesh cap = makeSphericalCap(1.0, thetaMax, rings);
    StraightestPathTracer tracer(cap, SurfacePoint::vertex(0));
    EXPECT_NEAR(tracer.base().normal.z, 1.0, 1e-12);  // symmetric boundary: the base normal is the axis
    double worst = 0;
    for (const auto& target : boundaryTargets(cap)) {
      const StraightestPath& path = tracer.trace(target);
      ASSERT_EQ(path.status, TraceStatus::Reached);
      EXPECT_LE(path.length, thetaMax + 1e-12);  // chords inside a convex cap are shorter than the arc
      worst = std::max(worst, thetaMax - path.length);
    }
    if (previousError > 0) {
      EXPECT_GT(previousError / worst, 3.0) << "rings " << rings;  // O(h²): ~4× per halving
      EXPECT_LT(previousError / worst, 5.0) << "rings " << rings;
    }
    previousError = worst;
  }
  EXPECT_LT(previousError, 1e-3);
}

/// Length of the cylinder section (R sinφ, k R sinφ, R cosφ), φ ∈ [0, θ] (an ellipse arc), by Simpson.
double cylinderSectionLength(double R, double k, double theta) {
  const int n = 2000;
  auto f = [&](double phi) {
    return R * std::sqrt(std::cos(phi) * std::cos(phi) * (1 + k * k) + std::sin(phi) * std::sin(phi));
  };
  double s = f(0) + f(theta);
  for (int i = 1; i < n; ++i) s += f(theta * i / n) * (i % 2 ? 4 : 2);
  return s * theta / (3 * n);
}

TEST(StraightestPathOnACylinder, FollowsTheEllipseCutByTheVerticalPlane) {
  // Cylinder x² + z² = R² around the y axis; the patch is symmetric about the source (0, 0, R), so the
  // base normal is the z axis and every cutting plane is vertical: the path is an ellipse arc.
  const double R = 2.0, alpha = 1.0;
  const int n = 61;
  const TriMesh mesh = testing::grid(n, GridPattern::UnionJack, [&](double i, double j) {
    const double theta = -alpha + 2 * alpha * i / (n - 1), y = -1.5 + 3.0 * j / (n - 1);
    return Vec3{R * std::sin(theta), y, R * std::cos(theta)};
  });
  const int32_t source = (n / 2) * n + n / 2;
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(source));
  EXPECT_NEAR(tracer.base().normal.z, 1.0, 1e-9);
  for (const auto& target : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(target);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const Vec3 D = position(mesh, target);
    const double theta = std::atan2(D.x, D.z);
    const double expected = std::abs(theta) < 1e-12 ? std::abs(D.y)
                                                    : cylinderSectionLength(R, D.y / D.x, std::abs(theta));
    EXPECT_NEAR(path.length, expected, 2e-3 * expected) << "target (" << D.x << ", " << D.y << ", " << D.z << ")";
  }
}

TEST(StraightestPathOnASaddle, FollowsTheParabolaOfEachVerticalPlane) {
  // z = x² − y² over the unit disk, source at the center: the section in direction φ is
  // z = r² cos 2φ, of length ∫₀¹ sqrt(1 + 4 r² cos² 2φ) dr.
  const TriMesh mesh = makeSample("saddle").value();
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(0));
  EXPECT_NEAR(tracer.base().normal.z, 1.0, 1e-9);
  for (const auto& target : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(target);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const Vec3 D = position(mesh, target);
    const double c = std::cos(2 * std::atan2(D.y, D.x));
    const double a = 2 * std::abs(c);
    const double expected = a < 1e-12 ? 1.0 : (std::sqrt(1 + a * a) / 2 + std::asinh(a) / (2 * a));
    EXPECT_NEAR(path.length, expected, 5e-3 * expected);
  }
}

TEST(StraightestPathOnAnLShape, HiddenTargetsFailInsteadOfGivingAWrongLength) {
  const int m = 8;
  const TriMesh mesh = testing::lShape(m);
  const int n = 2 * m + 1;
  const int32_t source = (2 * m - 2) * n + 2;  // in the upper arm, at (2, 2m − 2)
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(source));
  const Vec3 S = mesh.position(source);
  int hidden = 0, visible = 0;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) {
    if (mesh.vertexHalfedge(v) < 0) continue;
    const Vec3 D = mesh.position(v);
    // The segment S→D leaves the domain iff it passes through the open quadrant x > m, y > m.
    bool leaves = false;
    for (int k = 1; k < 1000; ++k) {
      const Vec3 p = S + (D - S) * (k / 1000.0);
      if (p.x > m + 1e-9 && p.y > m + 1e-9) leaves = true;
    }
    const StraightestPath& path = tracer.trace(SurfacePoint::vertex(v));
    if (leaves) {
      ++hidden;
      EXPECT_NE(path.status, TraceStatus::Reached) << "vertex " << v << " is not visible from the source";
      EXPECT_EQ(path.status, TraceStatus::HitBoundary);
    } else {
      ++visible;
      ASSERT_EQ(path.status, TraceStatus::Reached) << "vertex " << v;
      EXPECT_NEAR(path.length, norm(D - S), 1e-12 * (1 + norm(D - S)));
    }
  }
  EXPECT_GT(hidden, 10);
  EXPECT_GT(visible, 100);
}

TEST(StraightestPathOnAClosedSphere, EveryPairIsReachedAlongAGreatCircle) {
  const TriMesh sphere = testing::icosphere(3);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int32_t> vertex(0, sphere.numVertices() - 1);
  for (int s = 0; s < 20; ++s) {
    const int32_t source = vertex(rng);
    StraightestPathTracer tracer(sphere, SurfacePoint::vertex(source));
    EXPECT_NEAR(dot(tracer.base().normal, sphere.position(source)), 1.0, 1e-3);  // about radial
    for (int32_t v = 0; v < sphere.numVertices(); ++v) {
      if (v == source) continue;
      const StraightestPath& path = tracer.trace(SurfacePoint::vertex(v));
      const Vec3 S = sphere.position(source), D = sphere.position(v);
      const double angle = std::acos(std::clamp(dot(S, D), -1.0, 1.0));
      if (angle > kPi - 1e-6) continue;  // antipodal: the plane is undefined (n ∥ D − S)
      ASSERT_EQ(path.status, TraceStatus::Reached) << source << " → " << v;
      EXPECT_GE(path.length, norm(D - S) - 1e-12);
      EXPECT_NEAR(path.length, angle, 0.02 * angle + 1e-3) << source << " → " << v;
    }
  }
}

TEST(StraightestPathTracer, FailedTracesKeepTheirPartialPath) {
  const TriMesh mesh = testing::lShape(6);
  const int n = 13;
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(11 * n + 1));          // (1, 11), upper arm
  const StraightestPath& path = tracer.trace(SurfacePoint::vertex(3 * n + 11));  // (11, 3): behind the notch
  ASSERT_EQ(path.status, TraceStatus::HitBoundary);
  EXPECT_GE(path.positions.size(), 2u);
  EXPECT_GT(path.length, 0);
  expectConsecutivePointsShareAFace(mesh, path);
}

TEST(StraightestPathTracer, DestinationEqualToSourceIsReachedWithLengthZero) {
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(12));
  EXPECT_EQ(tracer.trace(SurfacePoint::vertex(12)).status, TraceStatus::Reached);
  EXPECT_EQ(tracer.trace(SurfacePoint::vertex(12)).length, 0);
}

TEST(StraightestPathTracer, DestinationAlongTheBaseNormalIsADegeneratePlane) {
  // A regular octahedron (closed: the base normal is the area-weighted normal). At the bottom apex S it
  // is −z by symmetry, and the top apex D lies straight above S: every plane through S perpendicular to
  // the base plane contains D, so none is determined by it.
  const TriMesh mesh = testing::buildOrFail({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                                            {{0, 2, 4},
                                             {2, 1, 4},
                                             {1, 3, 4},
                                             {3, 0, 4},  // top
                                             {2, 0, 5},
                                             {1, 2, 5},
                                             {3, 1, 5},
                                             {0, 3, 5}});  // bottom
  ASSERT_EQ(mesh.summary().eulerCharacteristic, 2);
  const int32_t bottom = 5, top = 4;
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(bottom));
  EXPECT_NEAR(tracer.base().normal.z, -1.0, 1e-12);
  EXPECT_FALSE(cuttingPlane(tracer.base(), mesh.position(top)).has_value());
  const StraightestPath& path = tracer.trace(SurfacePoint::vertex(top));
  EXPECT_EQ(path.status, TraceStatus::DegeneratePlane) << traceStatusName(path.status);
  EXPECT_EQ(path.length, 0);
  expectWellFormedPath(mesh, tracer, SurfacePoint::vertex(top), path);
  // Any other destination has its plane, and on this convex closed surface it is reached.
  for (int32_t v = 0; v < 4; ++v) {
    const StraightestPath& side = tracer.trace(SurfacePoint::vertex(v));
    EXPECT_EQ(side.status, TraceStatus::Reached) << "vertex " << v << ": " << traceStatusName(side.status);
    expectWellFormedPath(mesh, tracer, SurfacePoint::vertex(v), side);
  }
}

TEST(StraightestPathTracer, ThousandRandomPairsOnABumpyMeshGiveWellFormedWalks) {
  const TriMesh mesh = makeSample("face").value();
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> vertex(0, mesh.numVertices() - 1);
  int reached = 0;
  for (int s = 0; s < 25; ++s) {
    const SurfacePoint source = s % 2 ? SurfacePoint::vertex(vertex(rng)) : randomFacePoints(mesh, 1, 100 + s)[0];
    StraightestPathTracer tracer(mesh, source);
    auto targets = randomFacePoints(mesh, 20, 200 + s);
    for (int i = 0; i < 20; ++i) targets.push_back(SurfacePoint::vertex(vertex(rng)));
    for (const auto& target : targets) {
      const StraightestPath& path = tracer.trace(target);
      expectWellFormedPath(mesh, tracer, target, path);
      if (path.status == TraceStatus::Reached) {
        ++reached;
        EXPECT_GE(path.length, norm(position(mesh, target) - position(mesh, source)) - 1e-12);
      }
      EXPECT_LE(path.facesCrossed, 2 * mesh.numFaces() + mesh.numVertices() + 16);
    }
  }
  EXPECT_GT(reached, 500);  // most pairs on a face-like disk are reachable
}

TEST(TraceStraightestPaths, WithoutPointsGivesEverySingleTraceBitForBit) {
  // The samples and an L-shape give walks of very different lengths and endings (reached,
  // hit_boundary after both walks, same face, the source itself).
  for (const TriMesh& mesh : {makeSample("face").value(), makeSample("saddle").value(), makeSample("cap").value(),
                              makeSample("mountain").value(), testing::lShape(6)}) {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int32_t> vertex(0, mesh.numVertices() - 1);
    for (int s = 0; s < 6; ++s) {
      const SurfacePoint source = s % 2 ? SurfacePoint::vertex(vertex(rng)) : randomFacePoints(mesh, 1, 300 + s)[0];
      auto targets = randomFacePoints(mesh, 40, 400 + s);
      for (int i = 0; i < 60; ++i) targets.push_back(SurfacePoint::vertex(vertex(rng)));
      targets.push_back(source);
      const PathBatch batch = traceStraightestPaths(mesh, source, targets, TraceOptions{false}).value();
      ASSERT_EQ(batch.status.size(), targets.size());
      EXPECT_TRUE(batch.points.empty());
      StraightestPathTracer tracer(mesh, source);
      std::set<TraceStatus> kinds;
      for (size_t i = 0; i < targets.size(); ++i) {
        const StraightestPath& path = tracer.trace(targets[i]);
        ASSERT_EQ(batch.status[i], path.status) << "target " << i;
        EXPECT_EQ(batch.length[i], path.length) << "target " << i;
        EXPECT_EQ(batch.facesCrossed[i], path.facesCrossed) << "target " << i;
        EXPECT_EQ(batch.reversed[i] != 0, path.reversed) << "target " << i;
        kinds.insert(path.status);
      }
      EXPECT_TRUE(kinds.count(TraceStatus::Reached));
      if (mesh.numVertices() < 300) {
        EXPECT_GE(kinds.size(), 2u) << "the L-shape has unreachable targets";
      }
    }
  }
}

TEST(TraceStraightestPaths, PacksEveryPathWithItsOffsets) {
  const TriMesh mesh = makeSample("mountain").value();
  const SurfacePoint source = SurfacePoint::vertex(centerVertex(mesh));
  const PathBatch batch = traceStraightestPaths(mesh, source, boundaryTargets(mesh), TraceOptions{true}).value();
  ASSERT_EQ(batch.status.size(), mesh.boundaryLoops()[0].size());
  ASSERT_EQ(batch.offsets.size(), batch.status.size() + 1);
  EXPECT_EQ(batch.offsets.back(), static_cast<int64_t>(batch.points.size()));
  StraightestPathTracer tracer(mesh, source);
  for (size_t i = 0; i < batch.status.size(); ++i) {
    const StraightestPath& path = tracer.trace(batch.targets[i]);
    EXPECT_EQ(batch.status[i], path.status);
    EXPECT_EQ(batch.length[i], path.length);
    EXPECT_EQ(batch.offsets[i + 1] - batch.offsets[i], static_cast<int64_t>(path.positions.size()));
    if (batch.status[i] == TraceStatus::Reached) {
      const Vec3& last = batch.points[batch.offsets[i + 1] - 1];
      EXPECT_EQ(norm(last - position(mesh, batch.targets[i])), 0.0);  // ends exactly at the target
    }
  }
  EXPECT_GT(summarize(batch).reached, 0);
}

// Badly conditioned inputs give the well-conditioned answer (tolerances relative to the mesh's own
// scale) or a clear status, never a crash, a hang or a malformed path. Several were found by fuzzing
// (tests/fuzz/regressions keeps the raw inputs).

TEST(StraightestPathTracer, TargetNextToAVertexOnThePathIsReached) {
  // Flat 10 × 10 grid. From S = (2, 2) toward v = (6, 4) the section passes exactly through v; a target
  // on the edge v → (6, 5) at t = 1e-10 puts v on its cutting plane, yet none of the faces the walk
  // uses at v holds it. It must be reached, with the straight-line length.
  const TriMesh mesh = testing::flatGrid(10, GridPattern::Regular);
  const int32_t s = 2 * 10 + 2, v = 4 * 10 + 6, up = 5 * 10 + 6;
  const int32_t h = testing::findHalfedge(mesh, v, up);
  ASSERT_GE(h, 0);
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(s));
  for (double t : {1e-10, 1e-12, 1e-7}) {
    const SurfacePoint target = SurfacePoint::edge(h, t);
    const StraightestPath& path = tracer.trace(target);
    ASSERT_EQ(path.status, TraceStatus::Reached) << "t = " << t << ": " << traceStatusName(path.status);
    // The walk goes through v, then the last tiny step v → D: longer than |SD| by less than 2 |vD|.
    EXPECT_NEAR(path.length, norm(position(mesh, target) - mesh.position(s)), 2 * t + 1e-12) << "t = " << t;
    EXPECT_EQ(path.points.back().kind, SurfacePoint::Kind::Edge);
  }
}

TEST(StraightestPathTracer, SourceOnAnEdgeWithThePlaneAlmostAlongTheEdgeLeavesThroughAFace) {
  // Flat 10 × 10 grids, rotated and moved far from the origin; S at the midpoint of a diagonal edge,
  // D at t ≤ 1e-7 on an edge of the grid vertex one more cell along the diagonal, so the plane crosses
  // the source edge at S at an angle below ~5e-8. The computed crossing of that edge landed up to ~1e-6
  // from S (rounding at coordinates ~1000), was taken as the first step, and led the walk back through
  // the edge to S (other_component; hit_boundary in another run). Each target must be reached along
  // the straight segment.
  const int n = 10;
  for (double angle : {0.0, 0.3, 1.1, 2.5})
    for (const Vec3& offset : {Vec3{1000, -500, 250}, Vec3{-3000, 7000, 1}}) {
      const double c = std::cos(angle), s = std::sin(angle);
      const TriMesh mesh = testing::grid(n, GridPattern::Regular, [&](double x, double y) {
        return offset + Vec3{c * x - s * y, s * x + c * y, 0};
      });
      for (int i = 2; i <= 5; ++i)
        for (int j = 2; j <= 5; ++j) {
          // The diagonal of square (i, j), in whichever direction the grid splits it, and the vertex one
          // more cell along it (grid vertex (i, j) has index j n + i).
          int32_t a = j * n + i, b = a + n + 1, far = b + n + 1, di = 1;
          if (testing::findHalfedge(mesh, a, b) < 0) a = j * n + i + 1, b = a + n - 1, far = b + n - 1, di = -1;
          const int32_t h = testing::findHalfedge(mesh, a, b);
          ASSERT_GE(h, 0) << "no diagonal edge in square " << i << ", " << j;
          const Vec3 S = (mesh.position(a) + mesh.position(b)) * 0.5;
          StraightestPathTracer tracer(mesh, SurfacePoint::edge(h, 0.5));
          for (double t : {1e-7, 3e-8, 1e-9})
            for (int32_t next : {far - di, far - n}) {  // the edges from far back toward the diagonal's side
              const int32_t e = testing::findHalfedge(mesh, far, next);
              ASSERT_GE(e, 0);
              const SurfacePoint target = SurfacePoint::edge(e, t);
              const StraightestPath& path = tracer.trace(target);
              ASSERT_EQ(path.status, TraceStatus::Reached) << "angle " << angle << ", square " << i << ", " << j
                                                           << ", t " << t << ": " << traceStatusName(path.status);
              EXPECT_NEAR(path.length, norm(position(mesh, target) - S), 1e-9);
            }
        }
    }
}

TEST(StraightestPathTracer, PathsAreScaleInvariant) {
  const TriMesh base = makeSample("face").value();
  const int32_t source = defaultSource(base).value();
  const PathBatch reference =
      traceStraightestPaths(base, SurfacePoint::vertex(source), boundaryTargets(base), TraceOptions{false}).value();
  for (double s : {1e-6, 1e6}) {
    const TriMesh mesh = testing::scaled(base, s);
    EXPECT_EQ(defaultSource(mesh).value(), source);
    const PathBatch batch =
        traceStraightestPaths(mesh, SurfacePoint::vertex(source), boundaryTargets(mesh), TraceOptions{false}).value();
    ASSERT_EQ(batch.status.size(), reference.status.size());
    for (size_t i = 0; i < batch.status.size(); ++i) {
      EXPECT_EQ(batch.status[i], reference.status[i]) << "scale " << s << " path " << i;
      EXPECT_NEAR(batch.length[i] / s, reference.length[i], 1e-9 * reference.length[i]) << "scale " << s;
      EXPECT_EQ(batch.facesCrossed[i], reference.facesCrossed[i]);
    }
  }
}

TEST(StraightestPathOnAPlane, AlmostFlatPatchBehavesLikeAFlatOne) {
  const TriMesh mesh = testing::almostFlatGrid(21, 1e-10);
  const int32_t source = defaultSource(mesh).value();
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(source));
  EXPECT_NEAR(std::abs(tracer.base().normal.z), 1.0, 1e-12);
  for (const SurfacePoint& t : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(t);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const double euclid = norm(position(mesh, t) - mesh.position(source));
    EXPECT_NEAR(path.length, euclid, 1e-8 * euclid);
  }
}

TEST(StraightestPathOnAPlane, SliverTrianglesDoNotDerailTheWalk) {
  // A flat strip whose middle row of vertices sits 1e-9 above the line y = 1: the triangles along it
  // have angles ~1e-9. Paths across must still come out Euclidean (the plane is exactly the x-y plane).
  const int n = 11;
  const TriMesh mesh = testing::grid(n, GridPattern::Regular, [&](double x, double y) {
    return Vec3{x, y == 1 ? 1 + 1e-9 * x : y, 0};
  });
  EXPECT_EQ(mesh.summary().degenerateFaces, 0);
  StraightestPathTracer tracer(mesh, SurfacePoint::vertex(5 * n + 5));
  for (const SurfacePoint& t : boundaryTargets(mesh)) {
    const StraightestPath& path = tracer.trace(t);
    ASSERT_EQ(path.status, TraceStatus::Reached);
    const double euclid = norm(position(mesh, t) - mesh.position(5 * n + 5));
    EXPECT_NEAR(path.length, euclid, 1e-9 * euclid);
  }
}

TEST(StraightestPathTracer, NearDuplicateVerticesGiveWellFormedWalks) {
  // Two vertices 1e-13 apart (not welded: the file's vertex order is kept), each used by faces.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}, {0.5 + 1e-13, 0.5, 0}};
  std::vector<Triangle> t{{0, 1, 5}, {1, 2, 5}, {2, 3, 4}, {3, 0, 4}, {0, 5, 4}, {2, 4, 5}};
  const TriMesh mesh = testing::buildOrFail(p, t);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 1);
  EXPECT_EQ(mesh.summary().degenerateFaces, 2);  // the two slivers between the twins
  for (int32_t s : {4, 5}) {
    StraightestPathTracer tracer(mesh, SurfacePoint::vertex(s));
    for (int32_t v = 0; v < 4; ++v) {
      const StraightestPath& path = tracer.trace(SurfacePoint::vertex(v));
      expectWellFormedPath(mesh, tracer, SurfacePoint::vertex(v), path);
      if (path.status == TraceStatus::Reached) {
        EXPECT_NEAR(path.length, norm(p[v] - p[s]), 1e-9);
      }
    }
  }
}

TEST(StraightestPathOnASphericalCap, AlmostClosedCapGivesWellFormedWalksThatAgreeWithTheBatch) {
  // A sphere with a small hole at the bottom (polar angle π − 0.05), traced from the pole to the rim:
  // the base normal is the mean of nearly cancelling virtual-face normals (see BasePlane.AlmostClosedCap...);
  // the sections wrap almost all the way around the sphere.
  const TriMesh mesh = makeSphericalCap(1.0, kPi - 0.05, 24);
  const SurfacePoint pole = SurfacePoint::vertex(0);
  const std::vector<SurfacePoint> rim = boundaryTargets(mesh);
  const PathBatch batch = traceStraightestPaths(mesh, pole, rim, TraceOptions{false}).value();
  ASSERT_EQ(batch.status.size(), rim.size());
  StraightestPathTracer tracer(mesh, pole);
  for (size_t i = 0; i < rim.size(); ++i) {
    const StraightestPath& path = tracer.trace(rim[i]);
    expectWellFormedPath(mesh, tracer, rim[i], path);
    EXPECT_EQ(batch.status[i], path.status) << "target " << i;
    EXPECT_EQ(batch.length[i], path.length) << "target " << i;
  }
}

}  // namespace
}  // namespace straightest
