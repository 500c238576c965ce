// Straightest geodesics as an initial value problem (Polthier–Schmies): straight lines on a plane, helices
// of the analytic pitch on a cylinder, half of the total angle on each side through a vertex, the miss of a
// destination on a cone that the cutting plane reaches, the tangent frame's convention, and bad input.
#include "straightest/geodesics/geodesic_shoot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geodesic_surfaces.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/paths/base_plane.hpp"
#include "straightest/paths/straightest_path.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;
using testing::kPi;

double angle(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

/// The angle around v (counter-clockwise from vertexHalfedge(v), over the corner angles) of the direction
/// toward x, a point in one of the faces around v; and v's total angle.
std::pair<double, double> fanAngle(const TriMesh& mesh, int32_t v, const Vec3& x) {
  const Vec3 pv = mesh.position(v), r = x - pv;
  double before = 0, found = -1;
  for (int32_t h : mesh.outgoingHalfedges(v)) {
    const Vec3 u = mesh.position(mesh.head(h)) - pv, w = mesh.position(mesh.tail(TriMesh::prev(h))) - pv;
    const double corner = angle(u, w);
    if (found < 0 && std::fabs(angle(u, r) + angle(r, w) - corner) < 1e-9) found = before + angle(u, r);
    before += corner;
  }
  return {found, before};
}

/// The angles on the two sides of the path where it passes through point i (a vertex).
std::pair<double, double> sides(const TriMesh& mesh, const GeodesicShot& shot, size_t i) {
  const int32_t v = shot.points[i].index;
  const auto [in, total] = fanAngle(mesh, v, shot.positions[i - 1]);
  const double out = fanAngle(mesh, v, shot.positions[i + 1]).first;
  EXPECT_GE(in, 0);
  EXPECT_GE(out, 0);
  const double left = std::fmod(out - in + 2 * total, total);
  return {left, total - left};
}

TEST(GeodesicShoot, IsAStraightLineOnAPlane) {
  const TriMesh mesh = testing::flatGrid(15, GridPattern::Jittered);
  // Sources near the middle, so that 5 units never reach the boundary.
  const int32_t h = mesh.vertexHalfedge(7 * 15 + 7);
  for (const SurfacePoint& s : {SurfacePoint::vertex(7 * 15 + 7), SurfacePoint::face(TriMesh::face(h), {0.2, 0.3, 0.5}),
                                canonical(mesh, SurfacePoint::edge(TriMesh::next(h), 0.3), 1e-12)})
    for (double a : {0.1, 1.0, 2.5, 4.0}) {
      auto shot = shootGeodesicAtAngle(mesh, s, a, 5.0);
      ASSERT_TRUE(shot.ok()) << shot.error().message;
      const GeodesicShot& g = shot.value();
      EXPECT_EQ(g.status, ShootStatus::ReachedLength);
      EXPECT_NEAR(g.length, 5.0, 1e-12);
      const Vec3 start = g.positions.front(), dir = normalized(g.endPosition - start);
      EXPECT_NEAR(norm(g.endPosition - start), 5.0, 1e-12);
      EXPECT_GT(g.facesCrossed, 3);
      for (const Vec3& x : g.positions) EXPECT_NEAR(norm(cross(x - start, dir)), 0.0, 1e-12);
      // The angle is measured from the frame's axis, counter-clockwise about the normal (+z here).
      const TangentFrame frame = tangentFrame(mesh, s).value();
      EXPECT_NEAR(std::atan2(dot(cross(frame.axis0, dir), frame.normal), dot(frame.axis0, dir)),
                  std::remainder(a, 2 * kPi), 1e-12);
    }
}

TEST(GeodesicShoot, AngleZeroFollowsTheFirstOutgoingEdge) {
  const TriMesh mesh = testing::flatGrid(9, GridPattern::Regular);
  const int32_t v = 4 * 9 + 4;
  const GeodesicShot g = shootGeodesicAtAngle(mesh, SurfacePoint::vertex(v), 0.0, 0.5).value();
  const Vec3 edge = normalized(mesh.position(mesh.head(mesh.vertexHalfedge(v))) - mesh.position(v));
  EXPECT_NEAR(norm(g.endPosition - (mesh.position(v) + edge * 0.5)), 0.0, 1e-12);
}

// The start at a vertex, written out as geodesic_shoot.hpp states it (every sector's two angles by arctangents,
// the first sector holding the tangent, the same fraction of its corner angle): the walk, which passes most
// sectors without their arctangents, leaves in the same direction, bit for bit.
TEST(GeodesicShoot, AVertexSourceLeavesInTheSectorThatHoldsTheTangentBitForBit) {
  const TriMesh mesh = makeHeightField(12);
  auto signedAngle = [](const Vec3& a, const Vec3& b, const Vec3& n) {
    return std::atan2(dot(cross(a, b), n), dot(a, b));
  };
  auto projected = [](const Vec3& x, const Vec3& n) { return x - n * dot(x, n); };
  int compared = 0;
  for (int32_t v = 0; v < mesh.numVertices(); v += 5) {
    const TangentFrame frame = tangentFrame(mesh, SurfacePoint::vertex(v)).value();
    const Vec3& n = frame.normal;
    const Vec3& pv = mesh.position(v);
    for (int i = 0; i < 72; ++i) {
      const double angle = i * (2 * kPi / 72) + 1e-3;
      auto shot = shootGeodesicAtAngle(mesh, SurfacePoint::vertex(v), angle, 1e-3);
      const Vec3 tangent = normalized(projected(frame.axis0 * std::cos(angle) + frame.axis90 * std::sin(angle), n));
      for (int32_t h : mesh.outgoingHalfedges(v)) {
        const Vec3 p1 = projected(mesh.position(mesh.head(h)) - pv, n);
        const Vec3 p2 = projected(mesh.position(mesh.tail(TriMesh::prev(h))) - pv, n);
        const double sector = signedAngle(p1, p2, n), a = signedAngle(p1, tangent, n);
        if (!(sector > 0 && a >= 0 && a <= sector)) continue;
        const Vec3 u = mesh.position(mesh.head(h)) - pv, w = mesh.position(mesh.tail(TriMesh::prev(h))) - pv;
        const double beta = std::atan2(norm(cross(u, w)), dot(u, w)) * a / sector;
        const Vec3 e = normalized(u);
        const Vec3 expected = e * std::cos(beta) + cross(mesh.faceNormal(TriMesh::face(h)), e) * std::sin(beta);
        ASSERT_TRUE(shot) << shot.error().message;
        EXPECT_EQ(shot.value().direction.x, expected.x) << "vertex " << v << " angle " << i;
        EXPECT_EQ(shot.value().direction.y, expected.y) << "vertex " << v << " angle " << i;
        EXPECT_EQ(shot.value().direction.z, expected.z) << "vertex " << v << " angle " << i;
        ++compared;
        break;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(GeodesicShoot, IsAHelixOfTheAnalyticPitchOnACylinder) {
  const testing::Prism c = testing::prism(24, 60, 1.0, 0.1);
  const double gamma = 0.13;  // rise angle over the horizontal
  // A face point on ring 10 between corners 3 and 4: the face (corner 3, corner 4, ...) of that quad.
  const int32_t a = 10 * 24 + 3, b = a + 1;
  int32_t f = -1;
  for (int32_t k = 0; k < c.mesh.numFaces(); ++k) {
    const Triangle& t = c.mesh.triangle(k);
    if (t[0] == a && t[1] == b) f = k;
  }
  ASSERT_GE(f, 0);
  const SurfacePoint s = SurfacePoint::face(f, {0.6, 0.3, 0.1});
  const Vec3 horizontal = normalized(c.mesh.position(b) - c.mesh.position(a));
  const double length = 2.5 * c.perimeter();
  const GeodesicShot g =
      shootGeodesic(c.mesh, s, horizontal * std::cos(gamma) + Vec3{0, 0, 1} * std::sin(gamma), length).value();
  ASSERT_EQ(g.status, ShootStatus::ReachedLength);
  const double z0 = g.positions.front().z;
  EXPECT_NEAR(g.endPosition.z - z0, length * std::sin(gamma), 1e-9);
  // Vertical edges (polygon corners) are crossed one side's width apart, rising side · tan γ each time: a
  // pitch of perimeter · tan γ per turn.
  std::vector<double> cornerHeights;
  for (const Vec3& x : g.positions)
    if (std::fabs(std::hypot(x.x, x.y) - 1.0) < 1e-12) cornerHeights.push_back(x.z);
  ASSERT_GT(cornerHeights.size(), 50u);
  for (size_t i = 1; i < cornerHeights.size(); ++i)
    ASSERT_NEAR(cornerHeights[i] - cornerHeights[i - 1], c.side * std::tan(gamma), 1e-9);
  EXPECT_NEAR(cornerHeights[24] - cornerHeights[0], c.perimeter() * std::tan(gamma), 1e-9);
}

TEST(GeodesicShoot, LeavesAVertexWithHalfItsTotalAngleOnEachSide) {
  // Through the apex of a cone (total angle < 2π) along a ray of vertices (flat: π on each side), and
  // through a vertex of the mountain aimed at from inside one of its faces.
  const testing::Cone cone = testing::cone(6, 1.0, 1.0, 8);
  int32_t start = -1;
  for (int32_t v = 0; v < cone.mesh.numVertices(); ++v)
    if (cone.angle[v] == 0 && std::fabs(cone.radius[v] - 0.75 * norm(Vec3{1, 0, -1})) < 1e-12) start = v;
  ASSERT_GE(start, 0);
  const Vec3 toApex = cone.mesh.position(cone.apex) - cone.mesh.position(start);
  const GeodesicShot g = shootGeodesic(cone.mesh, SurfacePoint::vertex(start), toApex, 2 * norm(toApex)).value();
  int apexPassings = 0;
  for (size_t i = 1; i + 1 < g.points.size(); ++i) {
    if (g.points[i].kind != SurfacePoint::Kind::Vertex) continue;
    const auto [left, right] = sides(cone.mesh, g, i);
    EXPECT_NEAR(left, right, 1e-12) << "vertex " << g.points[i].index;
    apexPassings += g.points[i].index == cone.apex;
  }
  EXPECT_EQ(apexPassings, 1);

  const TriMesh mountain = makeSample("mountain").value();
  for (int32_t f : {700, 1500, 3000}) {
    const int32_t v = mountain.triangle(f)[2];
    const SurfacePoint s = SurfacePoint::face(f, {0.45, 0.45, 0.1});
    const Vec3 toV = mountain.position(v) - position(mountain, s);
    const GeodesicShot m = shootGeodesic(mountain, s, toV, 3 * norm(toV)).value();
    ASSERT_GE(m.points.size(), 3u);
    ASSERT_EQ(m.points[1], SurfacePoint::vertex(v));
    const auto [left, right] = sides(mountain, m, 1);
    EXPECT_NEAR(left, right, 1e-12) << "face " << f;
  }
}

TEST(GeodesicShoot, OnAConeMissesADestinationTheCuttingPlaneReaches) {
  // The paper's claim, measured: from S the cutting plane reaches D, while the geodesic shot in the
  // direction of D (projected on the base plane) passes beside it, bent by the apex's angle deficit.
  const testing::Cone cone = testing::cone(6, 1.0, 1.0, 16);
  const double r = 0.75 * norm(Vec3{1, 0, -1});
  int32_t s = -1, d = -1;
  for (int32_t v = 0; v < cone.mesh.numVertices(); ++v) {
    if (std::fabs(cone.radius[v] - r) > 1e-12) continue;
    if (std::fabs(cone.angle[v]) < 1e-12) s = v;
    if (std::fabs(cone.angle[v] - 2 * cone.faceAngle) < 1e-12) d = v;  // two faces (120° in space) around
  }
  ASSERT_GE(s, 0);
  ASSERT_GE(d, 0);
  StraightestPathTracer tracer(cone.mesh, SurfacePoint::vertex(s));
  ASSERT_EQ(tracer.trace(SurfacePoint::vertex(d)).status, TraceStatus::Reached);
  const GeodesicShot g = shootGeodesicToward(cone.mesh, SurfacePoint::vertex(s), SurfacePoint::vertex(d)).value();
  EXPECT_EQ(g.status, ShootStatus::ReachedLength);
  EXPECT_NEAR(g.length, g.straightestDistance, 1e-12);
  const double chord = norm(cone.mesh.position(d) - cone.mesh.position(s));
  EXPECT_GT(g.missDistance, 0.05 * chord);

  // On a plane the same shot hits: the projected direction is the geodesic's.
  const TriMesh plane = testing::flatGrid(11, GridPattern::Jittered);
  const GeodesicShot p = shootGeodesicToward(plane, SurfacePoint::vertex(5 * 11 + 5), SurfacePoint::vertex(2)).value();
  EXPECT_NEAR(p.missDistance, 0.0, 1e-12);
  EXPECT_NEAR(norm(p.endPosition - plane.position(2)), 0.0, 1e-12);
}

TEST(GeodesicShoot, WithoutThePolylineWalksTheSameWay) {
  // keepPoints = false keeps the source and the end only; the walk, its length, end, status and the miss
  // distance (measured as it goes) are those of the full polyline.
  const TriMesh mesh = makeHeightField(20);
  const SurfacePoint s = SurfacePoint::vertex(10 * 20 + 10);
  for (int32_t d : {0, 19, 7 * 20 + 3, 399, 15 * 20 + 12}) {
    ShootOptions lean;
    lean.keepPoints = false;
    const GeodesicShot full = shootGeodesicToward(mesh, s, SurfacePoint::vertex(d), 30.0).value();
    const GeodesicShot bare = shootGeodesicToward(mesh, s, SurfacePoint::vertex(d), 30.0, lean).value();
    EXPECT_EQ(bare.status, full.status);
    EXPECT_EQ(bare.facesCrossed, full.facesCrossed);
    EXPECT_EQ(bare.vertexPassings, full.vertexPassings);
    EXPECT_EQ(bare.length, full.length);
    EXPECT_EQ(bare.missDistance, full.missDistance);
    EXPECT_EQ(norm(bare.endPosition - full.endPosition), 0.0);
    ASSERT_EQ(bare.positions.size(), 2u);
    EXPECT_EQ(norm(bare.positions.back() - full.positions.back()), 0.0);
    // The miss distance is the polyline's closest approach.
    double miss = norm(full.target - full.positions.front());
    for (size_t i = 1; i < full.positions.size(); ++i) {
      const Vec3 e = full.positions[i] - full.positions[i - 1];
      const double t = std::clamp(dot(full.target - full.positions[i - 1], e) / dot(e, e), 0.0, 1.0);
      miss = std::min(miss, norm(full.target - (full.positions[i - 1] + e * t)));
    }
    EXPECT_NEAR(full.missDistance, miss, 1e-12);
  }
}

TEST(GeodesicShoot, WithoutThePolylineOrATargetEndsAtTheSamePoint) {
  // No target: the walk makes no 3D point as it goes, and still ends at the full polyline's last point.
  const TriMesh mesh = makeHeightField(20);
  ShootOptions lean;
  lean.keepPoints = false;
  for (int k = 0; k < 12; ++k) {
    const SurfacePoint s = SurfacePoint::vertex(10 * 20 + 10);
    const GeodesicShot full = shootGeodesicAtAngle(mesh, s, 0.53 * k, 25.0).value();
    const GeodesicShot bare = shootGeodesicAtAngle(mesh, s, 0.53 * k, 25.0, lean).value();
    EXPECT_EQ(bare.status, full.status);
    EXPECT_EQ(bare.facesCrossed, full.facesCrossed);
    EXPECT_EQ(bare.length, full.length);
    EXPECT_EQ(bare.end, full.end);
    EXPECT_EQ(norm(bare.endPosition - full.endPosition), 0.0);
    EXPECT_EQ(norm(full.positions.back() - full.endPosition), 0.0);
  }
}

TEST(GeodesicShoot, AShooterShootsTheSameGeodesicsBitForBit) {
  // A GeodesicShooter reads the faces' flat frames from its table; the functions compute the same records
  // as they walk. From a vertex, an edge point and a face point, winding around a cylinder and over a
  // height field until the boundary, with and without polylines and toward a destination.
  const testing::Prism c = testing::prism(24, 20, 1.0, 0.1);
  const TriMesh field = makeHeightField(20);
  for (const TriMesh* mesh : {&c.mesh, &field}) {
    const GeodesicShooter shooter = GeodesicShooter::make(*mesh).value();
    const SurfacePoint sources[] = {SurfacePoint::vertex(24 * 5 + 3), SurfacePoint::edge(3 * 150 + 1, 0.3),
                                    SurfacePoint::face(200, {0.3, 0.3, 0.4})};
    for (const SurfacePoint& s : sources) {
      for (int k = 0; k < 16; ++k) {
        for (bool keep : {false, true}) {
          ShootOptions options;
          options.keepPoints = keep;
          const GeodesicShot a = shootGeodesicAtAngle(*mesh, s, 0.41 * k, 40.0, options).value();
          const GeodesicShot b = shooter.shootAtAngle(s, 0.41 * k, 40.0, options).value();
          EXPECT_EQ(a.status, b.status);
          EXPECT_GT(a.facesCrossed, 0);
          EXPECT_EQ(a.facesCrossed, b.facesCrossed);
          EXPECT_EQ(a.vertexPassings, b.vertexPassings);
          EXPECT_EQ(a.length, b.length);
          EXPECT_EQ(a.end, b.end);
          ASSERT_EQ(a.positions.size(), b.positions.size());
          for (size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(norm(a.positions[i] - b.positions[i]), 0.0);
        }
      }
      const SurfacePoint d = SurfacePoint::vertex(mesh->numVertices() - 5);
      const GeodesicShot a = shootGeodesicToward(*mesh, s, d, 30.0).value();
      const GeodesicShot b = shooter.shootToward(s, d, 30.0).value();
      EXPECT_EQ(a.missDistance, b.missDistance);
      EXPECT_EQ(a.length, b.length);
      EXPECT_EQ(a.end, b.end);
    }
  }
}

TEST(GeodesicShoot, StopsAtTheBoundary) {
  const TriMesh mesh = testing::flatGrid(9, GridPattern::Jittered);
  const GeodesicShot g = shootGeodesicAtAngle(mesh, SurfacePoint::vertex(4 * 9 + 4), 0.3, 100.0).value();
  EXPECT_EQ(g.status, ShootStatus::HitBoundary);
  EXPECT_LT(g.length, 100.0);
  const Vec3 e = g.endPosition;
  EXPECT_TRUE(std::fabs(e.x) < 1e-12 || std::fabs(e.x - 8) < 1e-12 || std::fabs(e.y) < 1e-12 ||
              std::fabs(e.y - 8) < 1e-12);
}

TEST(GeodesicShoot, BadInputIsAnError) {
  const TriMesh mesh = testing::flatGrid(5, GridPattern::Regular);
  const SurfacePoint center = SurfacePoint::vertex(12);
  const double nan = std::nan("");
  auto category = [](const Expected<GeodesicShot>& r) { return r.ok() ? ErrorCode::Internal : r.error().code; };
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{0, 0, 0}, 1.0)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{nan, 0, 0}, 1.0)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{0, 0, 1}, 1.0)), ErrorCode::InvalidArgument);  // normal
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{1, 0, 0}, 0.0)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{1, 0, 0}, -1.0)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesic(mesh, center, Vec3{1, 0, 0}, nan)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesicAtAngle(mesh, center, nan, 1.0)), ErrorCode::InvalidArgument);
  EXPECT_EQ(category(shootGeodesic(mesh, SurfacePoint::vertex(99), Vec3{1, 0, 0}, 1.0)), ErrorCode::InvalidArgument);
  // On the boundary, pointing off the surface: vertex 2 is (2, 0), the surface lies at y >= 0.
  auto outward = shootGeodesic(mesh, SurfacePoint::vertex(2), Vec3{0.3, -1, 0}, 1.0);
  ASSERT_FALSE(outward.ok());
  EXPECT_NE(outward.error().message.find("off the surface"), std::string::npos);
  const int32_t boundaryEdge = mesh.boundaryLoops()[0].empty() ? -1 : [&] {
    for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h)
      if (mesh.isBoundaryHalfedge(h) && mesh.position(mesh.tail(h)).y == 0) return h;
    return -1;
  }();
  ASSERT_GE(boundaryEdge, 0);
  EXPECT_EQ(category(shootGeodesic(mesh, SurfacePoint::edge(boundaryEdge, 0.5), Vec3{0.2, -1, 0}, 1.0)),
            ErrorCode::InvalidArgument);
  EXPECT_TRUE(shootGeodesic(mesh, SurfacePoint::edge(boundaryEdge, 0.5), Vec3{0.2, 1, 0}, 1.0).ok());
  EXPECT_EQ(category(shootGeodesicToward(mesh, center, center)), ErrorCode::InvalidArgument);
}

TEST(GeodesicShoot, ReportsProgressAndCancels) {
  const testing::Prism c = testing::prism(24, 20, 1.0, 0.1);
  const Vec3 x = c.mesh.position(24 * 5 + 1) - c.mesh.position(24 * 5);
  // Winding many times around the cylinder at a shallow angle: long enough to report.
  auto cancelled = shootGeodesic(c.mesh, SurfacePoint::face(200, {0.3, 0.3, 0.4}), x + Vec3{0, 0, 1e-6}, 1e5, {},
                                 [](const char* stage, double f) { return std::string(stage) == "shoot" && f < 0.2; });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
}

}  // namespace
}  // namespace straightest
