// TriMesh validation, orientation repair and topology summaries.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"
#include "straightest/mesh/trimesh.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::dataPath;
using testing::loadGood;

ErrorCode buildError(std::vector<Vec3> p, std::vector<Triangle> t) {
  auto mesh = TriMesh::build(std::move(p), std::move(t));
  EXPECT_FALSE(mesh.ok());
  return mesh.ok() ? ErrorCode::InvalidArgument : mesh.error().code;
}

/// Every interior edge is traversed once in each direction: the definition of consistent orientation.
void expectConsistentlyOriented(const TriMesh& mesh) {
  std::set<std::pair<int, int>> directed;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto e = std::make_pair(mesh.triangle(f)[k], mesh.triangle(f)[(k + 1) % 3]);
      EXPECT_TRUE(directed.insert(e).second) << "edge " << e.first << "->" << e.second << " used twice";
    }
  for (int h = 0; h < 3 * mesh.numFaces(); ++h) {
    const int t = mesh.twin(h);
    if (t < 0) continue;
    EXPECT_EQ(mesh.tail(h), mesh.head(t));
    EXPECT_EQ(mesh.head(h), mesh.tail(t));
    EXPECT_EQ(mesh.twin(t), h);
  }
}

TEST(Orientation, FlipsTheMinorityToAgreeWithTheirNeighbours) {
  const TriMesh mesh = loadGood("good/inconsistent.obj");
  EXPECT_EQ(mesh.summary().reorientedFaces, 2);
  expectConsistentlyOriented(mesh);
  for (int f = 0; f < mesh.numFaces(); ++f) EXPECT_GT(mesh.faceNormal(f).z, 0.99) << "face " << f;
}

TEST(Orientation, ConsistentMeshIsLeftAlone) {
  const TriMesh mesh = loadGood("good/tetrahedron.off");
  EXPECT_EQ(mesh.summary().reorientedFaces, 0);
  expectConsistentlyOriented(mesh);
}

TEST(Orientation, MoebiusStripIsNonOrientable) {
  auto mesh = loadMeshFile(dataPath("bad/moebius.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::NonOrientable) << mesh.error().message;
}

TEST(Topology, DiskHasOneBoundaryLoopAndEulerCharacteristicOne) {
  const TriMesh mesh = loadGood("good/quad_grid.obj");
  ASSERT_EQ(mesh.boundaryLoops().size(), 1u);
  EXPECT_EQ(mesh.boundaryLoops()[0].size(), 8u);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 1);
  EXPECT_EQ(mesh.summary().components, 1);
  EXPECT_FALSE(mesh.isBoundaryVertex(4));  // the center of the 3 x 3 grid
}

TEST(Topology, BoundaryLoopKeepsTheSurfaceOnItsLeft) {
  // For a flat disk with upward normals, the boundary runs counter-clockwise: positive signed area.
  const TriMesh mesh = loadGood("good/quad_grid.obj");
  const auto& loop = mesh.boundaryLoops()[0];
  double twiceArea = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = mesh.position(loop[i]);
    const Vec3& b = mesh.position(loop[(i + 1) % loop.size()]);
    twiceArea += a.x * b.y - a.y * b.x;
  }
  EXPECT_NEAR(twiceArea / 2, 4.0, 1e-12);
}

TEST(Topology, AnnulusHasTwoLoopsAndEulerCharacteristicZero) {
  const TriMesh mesh = loadGood("good/annulus.off");
  EXPECT_EQ(mesh.boundaryLoops().size(), 2u);
  EXPECT_EQ(mesh.summary().boundaryLoopSizes, (std::vector<int64_t>{4, 4}));
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 0);
}

TEST(Topology, ClosedTetrahedronHasNoBoundaryAndEulerCharacteristicTwo) {
  const TriMesh mesh = loadGood("good/tetrahedron.off");
  EXPECT_TRUE(mesh.boundaryLoops().empty());
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 2);
  EXPECT_EQ(mesh.summary().edges, 6);
}

/// Faces and neighbours of v found by scanning every face (what the one-ring ranges must reproduce).
struct BruteForceRing {
  std::multiset<int> faces;
  std::set<int> neighbours;
};
BruteForceRing bruteForceRing(const TriMesh& mesh, int v) {
  BruteForceRing r;
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangle(f)[k] == v) {
        r.faces.insert(f);
        r.neighbours.insert(mesh.triangle(f)[(k + 1) % 3]);
        r.neighbours.insert(mesh.triangle(f)[(k + 2) % 3]);
      }
  return r;
}

/// The one-ring ranges of every vertex agree with the brute-force scan: each face around v once, each
/// outgoing halfedge leaves v and lies in the face listed with it, each neighbour once (a boundary
/// vertex has one more neighbour than faces, an interior one as many).
void expectRingsMatchBruteForce(const TriMesh& mesh) {
  for (int v = 0; v < mesh.numVertices(); ++v) {
    const BruteForceRing expected = bruteForceRing(mesh, v);
    std::vector<int> halfedges(mesh.outgoingHalfedges(v).begin(), mesh.outgoingHalfedges(v).end());
    std::vector<int> faces(mesh.vertexFaces(v).begin(), mesh.vertexFaces(v).end());
    std::vector<int> neighbours(mesh.vertexNeighbours(v).begin(), mesh.vertexNeighbours(v).end());
    EXPECT_EQ(std::multiset<int>(faces.begin(), faces.end()), expected.faces) << "vertex " << v;
    EXPECT_EQ(std::set<int>(neighbours.begin(), neighbours.end()), expected.neighbours) << "vertex " << v;
    EXPECT_EQ(std::set<int>(neighbours.begin(), neighbours.end()).size(), neighbours.size()) << "vertex " << v;
    ASSERT_EQ(halfedges.size(), faces.size());
    for (size_t k = 0; k < halfedges.size(); ++k) {
      EXPECT_EQ(mesh.tail(halfedges[k]), v);
      EXPECT_EQ(TriMesh::face(halfedges[k]), faces[k]);
      EXPECT_EQ(mesh.head(halfedges[k]), neighbours[k]);  // neighbours follow the halfedges' order
    }
    if (mesh.vertexHalfedge(v) >= 0) {
      EXPECT_EQ(neighbours.size(), faces.size() + (mesh.isBoundaryVertex(v) ? 1 : 0)) << "vertex " << v;
    }
  }
}

/// A hexagon fanned around vertex 0 at the origin, with `faces` of its 6 triangles (6: vertex 0 is
/// interior; fewer: on the boundary), and vertex 7 used by no face.
TriMesh hexagonFan(int faces) {
  std::vector<Vec3> p{{0, 0, 0}};
  for (int k = 0; k < 6; ++k) p.push_back({std::cos(k * kPi / 3), std::sin(k * kPi / 3), 0});
  p.push_back({5, 5, 5});
  std::vector<Triangle> t;
  for (int k = 0; k < faces; ++k) t.push_back({0, 1 + k, 1 + (k + 1) % 6});
  return TriMesh::build(std::move(p), std::move(t)).value();
}

TEST(VertexRing, InteriorVertexVisitsItsFacesAndNeighboursCounterClockwise) {
  const TriMesh mesh = hexagonFan(6);
  ASSERT_FALSE(mesh.isBoundaryVertex(0));
  std::vector<int> neighbours(mesh.vertexNeighbours(0).begin(), mesh.vertexNeighbours(0).end());
  EXPECT_EQ(neighbours.size(), 6u);
  EXPECT_EQ(std::distance(mesh.vertexFaces(0).begin(), mesh.vertexFaces(0).end()), 6);
  for (size_t k = 0; k < neighbours.size(); ++k) {  // each next neighbour 60° further counter-clockwise
    const Vec3 a = mesh.position(neighbours[k]), b = mesh.position(neighbours[(k + 1) % neighbours.size()]);
    EXPECT_GT(cross(a, b).z, 0.8);
    EXPECT_NEAR(dot(a, b), 0.5, 1e-12);
  }
  expectRingsMatchBruteForce(mesh);
}

TEST(VertexRing, BoundaryVertexStopsAtTheBoundaryAndEndsWithItsOtherBoundaryNeighbour) {
  for (int faces = 1; faces <= 5; ++faces) {
    const TriMesh mesh = hexagonFan(faces);
    ASSERT_TRUE(mesh.isBoundaryVertex(0));
    std::vector<int> neighbours(mesh.vertexNeighbours(0).begin(), mesh.vertexNeighbours(0).end());
    // Counter-clockwise from the boundary halfedge 0 → 1 to the last face's far corner.
    ASSERT_EQ(neighbours.size(), static_cast<size_t>(faces + 1));
    for (int k = 0; k <= faces; ++k) EXPECT_EQ(neighbours[k], 1 + k % 6) << faces << " faces";
    EXPECT_EQ(std::distance(mesh.vertexFaces(0).begin(), mesh.vertexFaces(0).end()), faces);
    expectRingsMatchBruteForce(mesh);
  }
}

TEST(VertexRing, UnreferencedVertexHasAnEmptyRing) {
  const TriMesh mesh = hexagonFan(4);
  ASSERT_LT(mesh.vertexHalfedge(7), 0);
  EXPECT_TRUE(mesh.outgoingHalfedges(7).begin() == mesh.outgoingHalfedges(7).end());
  EXPECT_TRUE(mesh.vertexFaces(7).begin() == mesh.vertexFaces(7).end());
  EXPECT_TRUE(mesh.vertexNeighbours(7).begin() == mesh.vertexNeighbours(7).end());
}

TEST(VertexRing, EveryVertexOfLargerMeshesMatchesTheFaceScan) {
  expectRingsMatchBruteForce(makeSample("mountain").value());  // a disk
  expectRingsMatchBruteForce(makeSample("cap").value());
  expectRingsMatchBruteForce(loadGood("good/tetrahedron.off"));  // closed: no boundary vertex
}

TEST(Topology, CountsComponentsAndUnreferencedVertices) {
  auto mesh = TriMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}},
                             {{0, 1, 2}, {4, 5, 6}});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().summary().components, 2);
  EXPECT_EQ(mesh.value().summary().unreferencedVertices, 1);
  EXPECT_EQ(mesh.value().summary().eulerCharacteristic, 2);
}

TEST(Validation, ReportsDegenerateFacesWithoutRejectingThem) {
  auto mesh = TriMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 3, 1}});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().summary().degenerateFaces, 1);  // (0, 3, 1) is collinear
  EXPECT_TRUE(mesh.value().isDegenerateFace(1));
  EXPECT_FALSE(mesh.value().isDegenerateFace(0));
}

TEST(Validation, RejectsNonManifoldEdge) {
  auto mesh = loadMeshFile(dataPath("bad/nonmanifold_edge.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::NonManifoldEdge);
  EXPECT_NE(mesh.error().message.find("3 faces"), std::string::npos) << mesh.error().message;
}

TEST(Validation, RejectsBowtieVertex) {
  auto mesh = loadMeshFile(dataPath("bad/nonmanifold_vertex.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::NonManifoldVertex) << mesh.error().message;
}

TEST(Validation, RejectsTwoClosedFansSharingAVertex) {
  // Two tetrahedra glued at one vertex: every edge is manifold, the shared vertex is not.
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  std::vector<Triangle> t{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 4, 5}, {0, 6, 4}, {4, 6, 5}, {0, 5, 6}};
  EXPECT_EQ(buildError(p, t), ErrorCode::NonManifoldVertex);
}

TEST(Validation, RejectsDuplicateFacesInEitherWinding) {
  auto mesh = loadMeshFile(dataPath("bad/duplicate_face.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::DuplicateFace) << mesh.error().message;
  EXPECT_EQ(buildError({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}), ErrorCode::DuplicateFace);
}

TEST(Validation, RejectsEmptyOutOfRangeRepeatedAndNonFinite) {
  EXPECT_EQ(buildError({}, {}), ErrorCode::Empty);
  EXPECT_EQ(buildError({{0, 0, 0}}, {}), ErrorCode::Empty);
  EXPECT_EQ(buildError({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}), ErrorCode::IndexOutOfRange);
  EXPECT_EQ(buildError({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, -1}}), ErrorCode::IndexOutOfRange);
  EXPECT_EQ(buildError({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 1}}), ErrorCode::InvalidFace);
  EXPECT_EQ(buildError({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}}), ErrorCode::NonFinite);
}

TEST(Validation, RefusesCoordinatesWhoseSquaredAreasOverflow) {
  // 1e100 gave faces of infinite area (|e1 × e2|² overflows; found by fuzzing); 1e40 is fine.
  const std::vector<Triangle> t{{0, 1, 2}};
  auto huge = TriMesh::build({{0, 0, 0}, {1e100, 0, 0}, {0, 1e100, 0}}, t);
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.error().code, ErrorCode::NonFinite);
  auto large = TriMesh::build({{0, 0, 0}, {1e40, 0, 0}, {0, 1e40, 0}}, t);
  ASSERT_TRUE(large.ok()) << large.error().message;
  EXPECT_TRUE(std::isfinite(large.value().faceArea(0)));
  EXPECT_NEAR(large.value().faceArea(0) / 0.5e80, 1.0, 1e-12);
}

TEST(Validation, TinyCoordinatesStillGiveUnitNormals) {
  // At 1e-155 the cross product's components are subnormal and squaring them underflows, so
  // |e1 × e2| computed naively is far from exact and the normal was not unit length (found by fuzz_ply).
  for (const double s : {1e-100, 1e-155, 1e-160}) {
    auto mesh = TriMesh::build({{0, 0, 0}, {s, 0, 0}, {0.3 * s, s, 0.2 * s}}, {{0, 1, 2}});
    ASSERT_TRUE(mesh.ok()) << s << ": " << mesh.error().message;
    const Vec3 n = mesh.value().faceNormal(0);
    EXPECT_NEAR(norm(n), 1.0, 1e-15) << s;
    EXPECT_GT(n.z, 0.9) << s;
    EXPECT_NEAR(n.y, -0.2 * n.z, 1e-6) << s;  // the plane y·0.2 = z through the three points
  }
}

TEST(Validation, EnforcesConfigurableCaps) {
  BuildLimits limits;
  limits.maxVertices = 2;
  auto mesh = TriMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, limits);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::TooLarge);
}

TEST(Validation, BoundingBoxSpansAllVertices) {
  const TriMesh mesh = loadGood("good/annulus.off");
  EXPECT_DOUBLE_EQ(mesh.summary().bbox.min.x, -2);
  EXPECT_DOUBLE_EQ(mesh.summary().bbox.max.y, 2);
  EXPECT_DOUBLE_EQ(mesh.summary().bbox.max.z, 0);
}

}  // namespace
}  // namespace straightest
