// The OFF reader: the header forms (OFF, COFF, NOFF, counts on the keyword's line), comments,
// polygons counted as faces, and strictness. The malformed corpus is checked in malformed_input_test.
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

TEST(OffReader, ToleratesCommentsAndBlankLines) {
  const TriMesh mesh = testing::loadGood("good/tetrahedron.off");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 4);
}

TEST(OffReader, AcceptsCountsOnTheHeaderLine) {
  auto mesh = loadMesh("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Auto);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(OffReader, TriangulatesANonConvexPolygonInsideItsOutline) {
  // An L-shaped hexagon listed from corner (2, 0): a fan from there would fold over the reflex corner.
  const std::string text = "OFF\n6 1 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 1 2 3 4 5 0\n";
  auto mesh = loadMesh(text);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  double area = 0;
  for (int f = 0; f < mesh.value().numFaces(); ++f) {
    area += mesh.value().faceArea(f);
    EXPECT_GT(mesh.value().faceNormal(f).z, 0.5) << "face " << f << " is flipped";
  }
  EXPECT_EQ(mesh.value().numFaces(), 4);
  EXPECT_NEAR(area, 3.0, 1e-12);
}

TEST(OffReader, CountsPolygonsAsFacesWhateverTheirTriangleCount) {
  // Two quads and a pentagon: 3 faces in the header, 2 + 2 + 3 triangles (a face-count bug found by the
  // CGAL benchmark: polygons were counted as their triangles).
  const std::string text =
      "OFF\n7 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n3 0.5 0\n"
      "4 0 1 2 3\n4 1 4 5 2\n5 4 6 5 2 1\n";
  auto mesh = loadMesh(text);
  ASSERT_FALSE(mesh.ok());  // the pentagon overlaps the second quad: a non-manifold edge, not a count error
  EXPECT_NE(mesh.error().code, ErrorCode::Parse) << mesh.error().message;
  auto quads = loadMesh("OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n4 0 1 2 3\n4 1 4 5 2\n");
  ASSERT_TRUE(quads.ok()) << quads.error().message;
  EXPECT_EQ(quads.value().numFaces(), 4);
}

TEST(OffReader, AcceptsColouredAndNormalVariants) {
  auto coff = loadMesh("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
  ASSERT_TRUE(coff.ok()) << coff.error().message;
  EXPECT_EQ(coff.value().position(1).x, 1.0);
  auto noff = loadMesh("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(noff.ok()) << noff.error().message;
  EXPECT_FALSE(loadMesh("OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n").ok());  // plain OFF stays strict
}

TEST(OffReader, AFaceColourMustBeNumeric) {
  EXPECT_TRUE(loadMesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0.5 0.5 1\n").ok());
  auto bad = loadMesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, "line 6: face 0: unexpected 'red' after its vertex indices");
}

TEST(OffReader, SignsCommentsAndOddSpacingReadLikeThePlainForm) {
  auto plain = parsePolygonSoup("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  auto odd = parsePolygonSoup(
      "OFF\n4 2 0\n+0 0. -0 # a comment\n\t1e0 0 .0\n1 +1 0\n\v0 1.0 0\f\n"
      "3 +0 1 2 # first\n  3\t0 2 +3\n");
  ASSERT_TRUE(plain.ok()) << plain.error().message;
  ASSERT_TRUE(odd.ok()) << odd.error().message;
  EXPECT_EQ(odd.value().triangles, plain.value().triangles);
  for (size_t v = 0; v < 4; ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(odd.value().positions[v][k], plain.value().positions[v][k]) << v;
}

TEST(OffReader, CountOverflowingInt64IsAParseError) {
  // Found by fuzz_off: a 19-digit count.
  auto off = loadMeshFile(testing::dataPath("../fuzz/regressions/fuzz_off/int64_overflow_count.off"));
  ASSERT_FALSE(off.ok());
  EXPECT_EQ(off.error().code, ErrorCode::Parse) << off.error().message;
}

}  // namespace
}  // namespace straightest
