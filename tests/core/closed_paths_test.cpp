// Straightest paths on closed surfaces: the section through S and D is a closed curve, walked both ways;
// the shorter arc is the path, the other arc's length and points come with it, and a destination on
// another component of the section is reported as such.
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

using testing::kPi;
using testing::polylineLength;

/// The surface point where the ray from the origin along dir leaves the mesh (the face it crosses,
/// with barycentric coordinates): on an icosphere, the mesh point in the direction dir.
SurfacePoint pointToward(const TriMesh& mesh, const Vec3& dir) {
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    const Vec3 a = mesh.position(t[0]), b = mesh.position(t[1]), c = mesh.position(t[2]);
    // Möller–Trumbore from the origin: s·dir = a + β(b − a) + γ(c − a).
    const Vec3 e1 = b - a, e2 = c - a, P = cross(dir, e2), T = a * -1.0, Q = cross(T, e1);
    const double det = dot(e1, P);
    if (!(std::abs(det) > 0)) continue;
    const double beta = dot(T, P) / det, gamma = dot(dir, Q) / det;
    if (!(dot(e2, Q) / det > 0)) continue;  // behind the origin
    const double alpha = 1 - beta - gamma;
    if (alpha < 0 || beta < 0 || gamma < 0) continue;
    return SurfacePoint::face(f, {alpha, beta, gamma});
  }
  ADD_FAILURE() << "no face toward the direction";
  return SurfacePoint::vertex(0);
}

/// dir rotated by angle about the unit axis (Rodrigues).
Vec3 rotate(const Vec3& dir, const Vec3& axis, double angle) {
  return dir * std::cos(angle) + cross(axis, dir) * std::sin(angle) + axis * (dot(axis, dir) * (1 - std::cos(angle)));
}

double axialRadius(const Vec3& p) { return std::sqrt(p.x * p.x + p.y * p.y); }

TEST(ClosedPathsOnASphere, BothArcsConvergeToTheGreatCircleQuadratically) {
  // S is an icosahedron vertex (five-fold symmetric: its area-weighted normal is radial), so every
  // cutting plane holds the centre and cuts the great circle through S and D: the shorter arc → R·θ,
  // the other → R·(2π − θ).
  const double R = 2.0;
  const Vec3 S = normalized(Vec3{-1, (1 + std::sqrt(5.0)) / 2, 0});  // vertex 0's direction
  std::vector<Vec3> directions;
  for (double theta : {0.7, 1.6, 2.5, 3.0})
    for (double azimuth : {0.3, 2.2, 4.1}) directions.push_back(rotate(S, rotate(Vec3{0, 0, 1}, S, azimuth), theta));
  double previousShort = 0, previousOther = 0;
  for (int level : {2, 3, 4, 5}) {
    const TriMesh sphere = makeIcosphere(R, level);
    ASSERT_TRUE(sphere.boundaryLoops().empty());
    StraightestPathTracer tracer(sphere, SurfacePoint::vertex(0));
    ASSERT_NEAR(dot(tracer.base().normal, S), 1.0, 1e-12);
    double worstShort = 0, worstOther = 0;
    for (const Vec3& dir : directions) {
      const SurfacePoint target = pointToward(sphere, dir);
      const double theta = std::acos(std::clamp(dot(S, normalized(dir)), -1.0, 1.0));
      const StraightestPath& path = tracer.trace(target);
      ASSERT_EQ(path.status, TraceStatus::Reached) << "level " << level << " θ " << theta;
      ASSERT_FALSE(std::isnan(path.otherArcLength));
      EXPECT_LE(path.length, path.otherArcLength);
      EXPECT_LT(path.length + path.otherArcLength, 2 * kPi * R);  // the whole section, an inscribed polygon
      EXPECT_GT(path.length + path.otherArcLength, 0.98 * 2 * kPi * R);
      // Inscribed polygons are shorter than the arcs.
      EXPECT_LT(path.length, R * theta + 1e-12);
      EXPECT_LT(path.otherArcLength, R * (2 * kPi - theta) + 1e-12);
      worstShort = std::max(worstShort, R * theta - path.length);
      worstOther = std::max(worstOther, R * (2 * kPi - theta) - path.otherArcLength);
      // Both arcs run from S to D in the cutting plane, and leave S on opposite sides.
      const CuttingPlane plane = cuttingPlane(tracer.base(), position(sphere, target)).value();
      const Vec3 t = inPlaneDirection(tracer.base(), position(sphere, target)).value();
      ASSERT_GE(path.positions.size(), 2u);
      ASSERT_GE(path.otherPositions.size(), 2u);
      for (const auto* arc : {&path.positions, &path.otherPositions}) {
        EXPECT_LE(norm(arc->front() - position(sphere, SurfacePoint::vertex(0))), 1e-12);
        EXPECT_LE(norm(arc->back() - position(sphere, target)), 1e-9);
        for (const Vec3& p : *arc) EXPECT_LE(std::abs(dot(plane.normal, p - plane.origin)), 1e-9 * R);
      }
      EXPECT_NEAR(polylineLength(path.positions), path.length, 1e-9);
      EXPECT_NEAR(polylineLength(path.otherPositions), path.otherArcLength, 1e-9);
      const double leaves = dot(path.positions[1] - path.positions[0], t);
      const double otherLeaves = dot(path.otherPositions[1] - path.otherPositions[0], t);
      EXPECT_EQ(path.reversed, leaves < 0);
      EXPECT_LT(leaves * otherLeaves, 0);
      // On a sphere the in-plane direction toward D points along the shorter arc: forward.
      EXPECT_FALSE(path.reversed) << "θ " << theta;
    }
    if (previousShort > 0) {
      std::printf("level %d: shorter-arc error %.3g (ratio %.2f), other-arc error %.3g (ratio %.2f)\n", level,
                  worstShort, previousShort / worstShort, worstOther, previousOther / worstOther);
      EXPECT_GT(previousShort / worstShort, 3.0) << "level " << level;  // O(h²): ~4× per halving
      EXPECT_LT(previousShort / worstShort, 5.0) << "level " << level;
      EXPECT_GT(previousOther / worstOther, 3.0) << "level " << level;
      EXPECT_LT(previousOther / worstOther, 5.0) << "level " << level;
    }
    previousShort = worstShort;
    previousOther = worstOther;
  }
  EXPECT_LT(previousShort, 1e-3 * R);
}

TEST(ClosedPathsOnASphere, TheBatchPacksBothArcsAndTheOtherLengths) {
  const TriMesh sphere = makeIcosphere(1.0, 3);
  const std::vector<SurfacePoint> targets{SurfacePoint::vertex(5), SurfacePoint::vertex(100), SurfacePoint::vertex(0)};
  const PathBatch batch = traceStraightestPaths(sphere, SurfacePoint::vertex(0), targets).value();
  StraightestPathTracer tracer(sphere, SurfacePoint::vertex(0));
  ASSERT_EQ(batch.otherArcLength.size(), targets.size());
  ASSERT_EQ(batch.otherOffsets.size(), targets.size() + 1);
  EXPECT_EQ(batch.otherOffsets.front(), 0);
  EXPECT_EQ(batch.otherOffsets.back(), static_cast<int64_t>(batch.otherPoints.size()));
  for (size_t i = 0; i < targets.size(); ++i) {
    const StraightestPath& path = tracer.trace(targets[i]);
    EXPECT_EQ(batch.status[i], path.status);
    EXPECT_EQ(batch.reversed[i], path.reversed);
    EXPECT_EQ(batch.length[i], path.length);
    const std::vector<Vec3> other(batch.otherPoints.begin() + batch.otherOffsets[i],
                                  batch.otherPoints.begin() + batch.otherOffsets[i + 1]);
    EXPECT_EQ(other.size(), path.otherPositions.size());
    if (std::isnan(path.otherArcLength)) {
      EXPECT_TRUE(std::isnan(batch.otherArcLength[i]));
      EXPECT_TRUE(other.empty());
    } else {
      EXPECT_EQ(batch.otherArcLength[i], path.otherArcLength);
      EXPECT_NEAR(polylineLength(other), path.otherArcLength, 1e-9);
    }
  }
  EXPECT_TRUE(std::isnan(batch.otherArcLength[2]));  // D == S: no section, no other arc
  EXPECT_FALSE(std::isnan(batch.otherArcLength[0]));
}

TEST(ClosedPathsOnASphere, ADestinationInTheSourcesFaceAlsoGetsTheLongWayRound) {
  const TriMesh sphere = makeIcosphere(1.0, 3);
  const Triangle& f = sphere.triangle(0);
  const SurfacePoint source = SurfacePoint::vertex(f[0]);
  const SurfacePoint target = SurfacePoint::face(0, {0.2, 0.5, 0.3});
  StraightestPathTracer tracer(sphere, source);
  const StraightestPath& path = tracer.trace(target);
  ASSERT_EQ(path.status, TraceStatus::Reached);
  EXPECT_EQ(path.facesCrossed, 1);
  EXPECT_NEAR(path.length, norm(position(sphere, target) - sphere.position(f[0])), 1e-15);
  // The rest of a plane section through S near the centre: about a great circle, inscribed.
  EXPECT_LT(path.length + path.otherArcLength, 2 * kPi);
  EXPECT_GT(path.length + path.otherArcLength, 0.97 * 2 * kPi);
  EXPECT_GT(path.otherPositions.size(), 10u);
}

TEST(ClosedPathsOnATorus, AMeridianAndTheOuterEquatorAreTheirCircles) {
  // Vertex (0, 0) sits on the outer equator, and the mesh is symmetric under the half turn about the x
  // axis through it, so its normal is x: the plane toward (0, k) is the meridian plane y = 0, toward
  // (i, 0) the equator plane z = 0. Both sections run along mesh edges (chords of the circles).
  const double R = 3, r = 1;
  const int around = 48, tube = 24;
  const TriMesh torus = makeTorus(R, r, around, tube);
  StraightestPathTracer tracer(torus, SurfacePoint::vertex(0));
  EXPECT_NEAR(tracer.base().normal.x, 1.0, 1e-12);
  const double meridianChord = 2 * r * std::sin(kPi / tube), equatorChord = 2 * (R + r) * std::sin(kPi / around);
  for (int k : {3, 10, 15}) {  // along the meridian: k tube steps, the other way tube − k
    const StraightestPath& path = tracer.trace(SurfacePoint::vertex(k));
    ASSERT_EQ(path.status, TraceStatus::Reached) << k;
    const int shorter = std::min(k, tube - k), longer = std::max(k, tube - k);
    EXPECT_NEAR(path.length, shorter * meridianChord, 1e-12);
    EXPECT_NEAR(path.otherArcLength, longer * meridianChord, 1e-12);
    const double arc = r * 2 * kPi * shorter / tube;  // the circle r·angle, chord by chord: 1 − sin x / x ≈ x²/6
    EXPECT_NEAR(path.length, arc, 3e-3 * arc);
    for (const Vec3& p : path.positions) EXPECT_NEAR(norm(p - Vec3{R, 0, 0}), r, 1e-12);
    for (const Vec3& p : path.otherPositions) EXPECT_NEAR(norm(p - Vec3{R, 0, 0}), r, 1e-12);
  }
  for (int i : {5, 20, 30}) {  // along the outer equator
    const StraightestPath& path = tracer.trace(SurfacePoint::vertex(i * tube));
    ASSERT_EQ(path.status, TraceStatus::Reached) << i;
    const int shorter = std::min(i, around - i), longer = std::max(i, around - i);
    EXPECT_NEAR(path.length, shorter * equatorChord, 1e-12);
    EXPECT_NEAR(path.otherArcLength, longer * equatorChord, 1e-12);
    const double arc = (R + r) * 2 * kPi * shorter / around;  // the circle (R + r)·angle
    EXPECT_NEAR(path.length, arc, 1e-3 * arc);
    for (const Vec3& p : path.positions) EXPECT_NEAR(axialRadius(p), R + r, 1e-12);
  }
}

TEST(ClosedPathsOnATorus, ADestinationOnTheInnerEquatorIsOnAnotherComponentOfTheSection) {
  // From the outer equator toward a point of the inner equator the cutting plane is z = 0 (it holds
  // the radial normal at S and D − S, both horizontal), which cuts the torus in two circles: the outer
  // one through S, of radius R + r, and the inner one through D, of radius R − r. Each walk goes
  // once round the outer circle and comes back to S.
  const double R = 3, r = 1;
  const int around = 48, tube = 24;
  const TriMesh torus = makeTorus(R, r, around, tube);
  StraightestPathTracer tracer(torus, SurfacePoint::vertex(0));
  for (int i : {5, 17, 31}) {
    const SurfacePoint target = SurfacePoint::vertex(i * tube + tube / 2);  // (i, tube/2): the inner equator
    const Vec3 D = position(torus, target);
    ASSERT_NEAR(axialRadius(D), R - r, 1e-12);
    const CuttingPlane plane = cuttingPlane(tracer.base(), D).value();
    EXPECT_NEAR(std::abs(plane.normal.z), 1.0, 1e-12);  // z = 0
    const StraightestPath& path = tracer.trace(target);
    EXPECT_EQ(path.status, TraceStatus::OtherComponent) << i;
    EXPECT_STREQ(traceStatusName(path.status), "other_component");
    EXPECT_TRUE(std::isnan(path.otherArcLength));
    EXPECT_TRUE(path.otherPositions.empty());
    // The whole outer circle, every point 2r away from D's component.
    EXPECT_NEAR(path.length, around * 2 * (R + r) * std::sin(kPi / around), 1e-9);
    EXPECT_NEAR(norm(path.positions.back() - path.positions.front()), 0, 1e-12);
    for (const Vec3& p : path.positions) {
      EXPECT_NEAR(axialRadius(p), R + r, 1e-12);
      EXPECT_NEAR(p.z, 0, 1e-12);
    }
  }
}

TEST(ClosedPathsOnATorus, RandomPairsAreReachedOrOnAnotherComponentAndNeverLongerThanTheOtherArc) {
  const TriMesh torus = makeTorus(3, 1, 40, 20);
  int reached = 0, other = 0;
  for (int32_t s : {0, 7, 210, 333}) {
    StraightestPathTracer tracer(torus, SurfacePoint::vertex(s));
    for (int32_t v = 0; v < torus.numVertices(); v += 7) {
      const StraightestPath& path = tracer.trace(SurfacePoint::vertex(v));
      if (path.status == TraceStatus::OtherComponent) {
        ++other;
        EXPECT_NEAR(norm(path.positions.back() - path.positions.front()), 0, 1e-9);  // back at S
        continue;
      }
      if (path.status != TraceStatus::Reached) continue;
      ++reached;
      if (std::isnan(path.otherArcLength)) continue;
      EXPECT_LE(path.length, path.otherArcLength);
      EXPECT_NEAR(polylineLength(path.otherPositions), path.otherArcLength, 1e-9);
    }
  }
  EXPECT_GT(reached, 100);
  EXPECT_GT(other, 10);
}

TEST(PathsWithABoundary, NeverReportAnOtherArc) {
  // A disk keeps the paper's rule: the first walk that reaches D, nothing walked the other way.
  const TriMesh mesh = makeSample("mountain").value();
  const SurfacePoint source = resolveSource(mesh, std::nullopt).value();
  const PathBatch batch = traceStraightestPaths(mesh, source, boundaryTargets(mesh)).value();
  for (double l : batch.otherArcLength) EXPECT_TRUE(std::isnan(l));
  EXPECT_TRUE(batch.otherPoints.empty());
  ASSERT_EQ(batch.otherOffsets.size(), batch.status.size() + 1);
  for (int64_t o : batch.otherOffsets) EXPECT_EQ(o, 0);
}

}  // namespace
}  // namespace straightest
