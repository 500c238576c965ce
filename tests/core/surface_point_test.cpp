// Surface points: one canonical representation per location, the one snapping rule, validation.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/mesh/surface_point.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

using testing::GridPattern;

/// A flat 3×3-vertex grid (8 faces): vertex 4 is interior, the others on the boundary.
TriMesh grid() { return testing::flatGrid(3, GridPattern::Regular); }

/// The halfedge from vertex a to vertex b (-1 if there is none).
int32_t halfedge(const TriMesh& mesh, int32_t a, int32_t b) {
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h)
    if (mesh.tail(h) == a && mesh.head(h) == b) return h;
  return -1;
}

/// Barycentric coordinates for the point with the given weights on vertices of face f (others 0).
std::array<double, 3> baryOf(const TriMesh& mesh, int32_t f, int32_t v1, double w1, int32_t v2, double w2) {
  std::array<double, 3> b{};
  for (int k = 0; k < 3; ++k) {
    if (mesh.triangle(f)[k] == v1) b[k] += w1;
    if (mesh.triangle(f)[k] == v2) b[k] += w2;
  }
  return b;
}

/// A face holding both vertices a and b, other than `other`.
int32_t faceWith(const TriMesh& mesh, int32_t a, int32_t b, int32_t other = -1) {
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Triangle& t = mesh.triangle(f);
    const bool hasA = t[0] == a || t[1] == a || t[2] == a, hasB = t[0] == b || t[1] == b || t[2] == b;
    if (hasA && hasB && f != other) return f;
  }
  return -1;
}

double distance(const TriMesh& mesh, const SurfacePoint& a, const SurfacePoint& b) {
  return norm(position(mesh, a) - position(mesh, b));
}

TEST(SurfacePoint, BothHalfedgesOfAnInteriorEdgeGiveOneForm) {
  const TriMesh mesh = grid();
  const int32_t h = halfedge(mesh, 4, 5), t = mesh.twin(h);
  ASSERT_GE(h, 0);
  ASSERT_GE(t, 0);
  for (double s : {0.25, 0.5, 0.625}) {  // 1 − s is exact: the two forms must agree bit for bit
    const SurfacePoint a = canonical(mesh, SurfacePoint::edge(h, s), kExactSnap);
    const SurfacePoint b = canonical(mesh, SurfacePoint::edge(t, 1 - s), kExactSnap);
    EXPECT_EQ(a, b) << "t = " << s;
    EXPECT_EQ(a.kind, SurfacePoint::Kind::Edge);
    EXPECT_EQ(a.index, std::min(h, t));  // the rule: the smaller halfedge
    EXPECT_EQ(distance(mesh, a, SurfacePoint::edge(h, s)), 0);
  }
  // Any t: the same halfedge, t within an ulp of 1 − (1 − t), and the same place.
  const SurfacePoint a = canonical(mesh, SurfacePoint::edge(h, 0.3), kExactSnap);
  const SurfacePoint b = canonical(mesh, SurfacePoint::edge(t, 0.7), kExactSnap);
  EXPECT_EQ(a.index, b.index);
  EXPECT_NEAR(a.t, b.t, 1e-16);
  EXPECT_LE(distance(mesh, a, b), 1e-15);
}

TEST(SurfacePoint, ABoundaryEdgeKeepsItsOnlyHalfedge) {
  const TriMesh mesh = grid();
  const int32_t h = halfedge(mesh, 0, 1) >= 0 ? halfedge(mesh, 0, 1) : halfedge(mesh, 1, 0);
  ASSERT_GE(h, 0);
  ASSERT_LT(mesh.twin(h), 0);
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 0.3), kExactSnap), SurfacePoint::edge(h, 0.3));
}

TEST(SurfacePoint, VertexEdgeAndFacePointsAtACornerCompareEqual) {
  const TriMesh mesh = grid();
  const SurfacePoint v = SurfacePoint::vertex(4);
  std::vector<SurfacePoint> forms;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); ++h) {  // every halfedge at vertex 4, from either end
    if (mesh.tail(h) == 4) forms.push_back(SurfacePoint::edge(h, 0));
    if (mesh.head(h) == 4) forms.push_back(SurfacePoint::edge(h, 1));
  }
  for (int32_t f = 0; f < mesh.numFaces(); ++f)  // every face at vertex 4
    for (int k = 0; k < 3; ++k)
      if (mesh.triangle(f)[k] == 4) {
        std::array<double, 3> b{};
        b[k] = 1;
        forms.push_back(SurfacePoint::face(f, b));
      }
  ASSERT_EQ(forms.size(), 2 * 6 + 6u);  // vertex 4 has 6 edges (12 halfedges) and 6 faces
  for (const SurfacePoint& p : forms) {
    EXPECT_EQ(canonical(mesh, p, kExactSnap), v);
    auto valid = validateSurfacePoint(mesh, p);
    ASSERT_TRUE(valid.ok());
    EXPECT_EQ(valid.value(), v);
  }
}

TEST(SurfacePoint, FacePointsOnAnEdgeFromEitherFaceCompareEqual) {
  const TriMesh mesh = grid();
  const int32_t f = faceWith(mesh, 4, 5), g = faceWith(mesh, 4, 5, f);
  ASSERT_GE(f, 0);
  ASSERT_GE(g, 0);
  const SurfacePoint fromF = SurfacePoint::face(f, baryOf(mesh, f, 4, 0.75, 5, 0.25));
  const SurfacePoint fromG = SurfacePoint::face(g, baryOf(mesh, g, 4, 0.75, 5, 0.25));
  const SurfacePoint onEdge = canonical(mesh, SurfacePoint::edge(halfedge(mesh, 5, 4), 0.75), kExactSnap);
  EXPECT_EQ(canonical(mesh, fromF, kExactSnap), onEdge);
  EXPECT_EQ(canonical(mesh, fromG, kExactSnap), onEdge);
  EXPECT_EQ(validateSurfacePoint(mesh, fromF).value(), onEdge);
  EXPECT_EQ(validateSurfacePoint(mesh, fromG).value(), onEdge);
  EXPECT_EQ(onEdge.kind, SurfacePoint::Kind::Edge);
  EXPECT_LE(distance(mesh, onEdge, fromF), 1e-15);
}

TEST(SurfacePoint, CanonicalIsIdempotentAndKeepsThePosition) {
  const TriMesh mesh = testing::flatGrid(6, GridPattern::Jittered);
  std::vector<SurfacePoint> points;
  for (int32_t h = 0; h < 3 * mesh.numFaces(); h += 5) points.push_back(SurfacePoint::edge(h, 0.37));
  for (int32_t f = 0; f < mesh.numFaces(); f += 3) {
    points.push_back(SurfacePoint::face(f, {0.2, 0.3, 0.5}));
    points.push_back(SurfacePoint::face(f, {0.0, 0.4, 0.6}));
    points.push_back(SurfacePoint::face(f, {5e-7, 0.5, 0.5 - 5e-7}));
  }
  for (double tolerance : {kExactSnap, kSnapSource})
    for (const SurfacePoint& p : points) {
      const SurfacePoint c = canonical(mesh, p, tolerance);
      EXPECT_EQ(canonical(mesh, c, tolerance), c);
      EXPECT_LE(distance(mesh, c, p), 2 * tolerance * mesh.meanEdgeLength() + 1e-15);
      if (c.kind == SurfacePoint::Kind::Edge) {
        EXPECT_GT(c.t, tolerance);
        EXPECT_LT(c.t, 1 - tolerance);
        if (mesh.twin(c.index) >= 0) {
          EXPECT_LT(c.index, mesh.twin(c.index));
        }
      }
    }
}

TEST(SurfacePoint, SnapsWithinTheToleranceAndNotBeyond) {
  const TriMesh mesh = grid();
  const int32_t h = halfedge(mesh, 4, 5);
  // Edge parameters: within the tolerance of an end → that vertex; just outside → still the edge.
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 1e-7), kSnapSource), SurfacePoint::vertex(4));
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 1 - 1e-7), kSnapSource), SurfacePoint::vertex(5));
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 2e-6), kSnapSource).kind, SurfacePoint::Kind::Edge);
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 1e-7), kExactSnap).kind, SurfacePoint::Kind::Edge);
  EXPECT_EQ(canonical(mesh, SurfacePoint::edge(h, 1e-13), kExactSnap), SurfacePoint::vertex(4));

  // Face points: one small coordinate → the opposite edge, two → the remaining corner.
  const int32_t f = faceWith(mesh, 4, 5);
  const SurfacePoint nearEdge = SurfacePoint::face(f, baryOf(mesh, f, 4, 0.5, 5, 0.5 - 1e-7));
  std::array<double, 3> b = nearEdge.bary;
  for (double& x : b)
    if (x == 0) x = 1e-7;  // the third corner's coordinate: 1e-7
  const SurfacePoint p = SurfacePoint::face(f, b);
  const SurfacePoint snapped = canonical(mesh, p, kSnapSource);
  ASSERT_EQ(snapped.kind, SurfacePoint::Kind::Edge);
  EXPECT_EQ(snapped.index, std::min(h, mesh.twin(h)));
  EXPECT_LE(distance(mesh, snapped, p), 1e-6);
  EXPECT_EQ(canonical(mesh, p, kExactSnap), p);  // far above the exact snap: left alone

  const SurfacePoint nearCorner = SurfacePoint::face(f, baryOf(mesh, f, 4, 1 - 2e-7, 5, 1e-7));
  std::array<double, 3> c = nearCorner.bary;
  for (double& x : c)
    if (x == 0) x = 1e-7;
  EXPECT_EQ(canonical(mesh, SurfacePoint::face(f, c), kSnapSource), SurfacePoint::vertex(4));
}

TEST(SurfacePoint, ValidationNormalizesAndRefusesBadPoints) {
  const TriMesh mesh = grid();
  auto p = validateSurfacePoint(mesh, SurfacePoint::face(0, {0.2, 0.3, 0.5 + 5e-10}));
  ASSERT_TRUE(p.ok());
  EXPECT_NEAR(p.value().bary[0] + p.value().bary[1] + p.value().bary[2], 1, 1e-15);
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::face(0, {0.2, 0.3, 0.6})).ok());   // sum 1.1
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::face(0, {-0.1, 0.6, 0.5})).ok());  // negative
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::face(mesh.numFaces(), {1, 0, 0})).ok());
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::edge(0, 1.5)).ok());
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::edge(0, NAN)).ok());
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::edge(3 * mesh.numFaces(), 0.5)).ok());
  EXPECT_FALSE(validateSurfacePoint(mesh, SurfacePoint::vertex(-1)).ok());
  EXPECT_EQ(validateSurfacePoint(mesh, SurfacePoint::vertex(-1)).error().code, ErrorCode::InvalidArgument);
}

TEST(SurfacePoint, EqualityComparesTheRepresentation) {
  EXPECT_EQ(SurfacePoint::vertex(3), SurfacePoint::vertex(3));
  EXPECT_NE(SurfacePoint::vertex(3), SurfacePoint::vertex(4));
  EXPECT_NE(SurfacePoint::edge(3, 0.5), SurfacePoint::edge(3, 0.25));
  EXPECT_NE(SurfacePoint::edge(3, 0.5), SurfacePoint::vertex(3));
  EXPECT_EQ(SurfacePoint::face(2, {0.2, 0.3, 0.5}), SurfacePoint::face(2, {0.2, 0.3, 0.5}));
  EXPECT_NE(SurfacePoint::face(2, {0.2, 0.3, 0.5}), SurfacePoint::face(2, {0.3, 0.2, 0.5}));
}

}  // namespace
}  // namespace straightest
