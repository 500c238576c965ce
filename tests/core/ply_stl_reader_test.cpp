// The PLY and STL readers (ply_reader.hpp, stl_reader.hpp): the same unit cube written as OBJ, ASCII
// PLY, little- and big-endian binary PLY, ASCII and binary STL (tests/data/good/cube*) loads to one
// mesh, whatever the format, encoding and skipped properties; STL corners weld into shared vertices;
// the content alone tells the formats apart. Malformed files are in the corpus (malformed_input_test).
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::dataPath;
using testing::loadGood;
using testing::readFile;

void expectSameMesh(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.numVertices(), b.numVertices());
  ASSERT_EQ(a.numFaces(), b.numFaces());
  for (int32_t v = 0; v < a.numVertices(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.position(v)[k], b.position(v)[k]) << "vertex " << v;
  for (int32_t f = 0; f < a.numFaces(); ++f) EXPECT_EQ(a.triangle(f), b.triangle(f)) << "face " << f;
}

TEST(PlyStlReaders, TheCubeLoadsToTheSameMeshInEveryFormatAndEncoding) {
  const TriMesh reference = loadGood("good/cube.obj");
  ASSERT_EQ(reference.numVertices(), 8);
  ASSERT_EQ(reference.summary().eulerCharacteristic, 2);
  for (const char* file : {"good/cube_ascii.ply", "good/cube_binary_le.ply", "good/cube_binary_be.ply",
                           "good/cube_ascii.stl", "good/cube_binary.stl"}) {
    SCOPED_TRACE(file);
    const TriMesh mesh = loadGood(file);
    expectSameMesh(mesh, reference);
    EXPECT_EQ(mesh.summary().reorientedFaces, 0);
    // The bytes alone (no file name) give the same mesh: the content tells the format.
    auto fromBytes = loadMesh(readFile(dataPath(file)));
    ASSERT_TRUE(fromBytes.ok()) << fromBytes.error().message;
    expectSameMesh(fromBytes.value(), reference);
  }
}

TEST(PlyStlReaders, StlCornersWeldByExactEquality) {
  // 36 corners in the file, 8 distinct points: 8 vertices, each shared by its faces.
  auto soup = parsePolygonSoup(readFile(dataPath("good/cube_binary.stl")), MeshFormat::Stl);
  ASSERT_TRUE(soup.ok()) << soup.error().message;
  EXPECT_EQ(soup.value().positions.size(), 8u);
  EXPECT_EQ(soup.value().triangles.size(), 12u);
  // Two triangles whose shared corners differ in the last bit stay apart (no tolerance), −0 and +0 weld.
  const double nudged = std::nextafter(1.0, 2.0);
  const std::string text =
      "solid s\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 1 0\n"
      " endloop\n endfacet\n facet normal 0 0 1\n outer loop\n vertex -0 0 0\n vertex 1 1 0\n"
      " vertex 1 0 0\n endloop\n endfacet\n facet normal 0 0 1\n outer loop\n vertex 1.0000000000000002 0 0\n"
      " vertex 1 1 0\n vertex 2 0 0\n endloop\n endfacet\nendsolid s\n";
  ASSERT_EQ(std::stod("1.0000000000000002"), nudged);
  auto welded = parsePolygonSoup(text, MeshFormat::Auto);
  ASSERT_TRUE(welded.ok()) << welded.error().message;
  EXPECT_EQ(welded.value().positions.size(), 6u);  // (0,0,0) (1,0,0) (0,1,0) (1,1,0) (1+ε,0,0) (2,0,0)
  EXPECT_EQ(welded.value().triangles[1][0], 0);    // −0 is the first vertex
}

TEST(PlyStlReaders, StlTrianglesCollapsedByWeldingAreDroppedAndNoted) {
  std::string stl = readFile(dataPath("good/cube_ascii.stl"));
  const std::string sliver =
      " facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 0 0 0\n vertex 1 1 1\n"
      " endloop\n endfacet\n";
  stl.insert(stl.rfind("endsolid"), sliver);
  auto mesh = loadMesh(stl);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 12);
  bool noted = false;
  for (const std::string& note : mesh.value().summary().problems) noted = noted || note.find("1 STL triangles") == 0;
  EXPECT_TRUE(noted);
}

TEST(PlyStlReaders, PlyPolygonsAreTriangulatedAndOtherElementsSkipped) {
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment a square as one quad\nelement vertex 4\nproperty double x\nproperty double y\n"
      "property double z\nproperty list uchar float weights\nelement face 1\nproperty list int uint vertex_index\n"
      "element material 2\nproperty uchar index\nend_header\n0 0 0 0\n1 0 0 2 0.5 0.5\n1 1 0 0\n0 1 0 1 1\n"
      "4 0 1 2 3\n0\n1\n";
  auto soup = parsePolygonSoup(ply);
  ASSERT_TRUE(soup.ok()) << soup.error().message;
  EXPECT_EQ(soup.value().positions.size(), 4u);
  EXPECT_EQ(soup.value().triangles.size(), 2u);
  EXPECT_EQ(soup.value().polygonsTriangulated, 1);
  EXPECT_EQ(soup.value().positions[1].x, 1.0);
}

TEST(PlyStlReaders, BinaryPlyDoublesKeepEveryBit) {
  const double x = 0.1, y = -1.0 / 3.0, z = 1e-300;
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const double coords[9] = {x, y, z, 1, 0, 0, 0, 1, 0};
  ply.append(reinterpret_cast<const char*>(coords), sizeof coords);
  const unsigned char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
  ply.append(reinterpret_cast<const char*>(face), sizeof face);
  auto soup = parsePolygonSoup(ply, MeshFormat::Ply);
  ASSERT_TRUE(soup.ok()) << soup.error().message;
  EXPECT_EQ(soup.value().positions[0].x, x);
  EXPECT_EQ(soup.value().positions[0].y, y);
  EXPECT_EQ(soup.value().positions[0].z, z);
}

TEST(PlyStlReaders, HeadersThatClaimMoreThanTheFileHoldsFailBeforeAllocating) {
  BuildLimits limits;
  limits.maxVertices = 100;
  auto tooMany = parsePolygonSoup(
      "ply\nformat ascii 1.0\nelement vertex 101\nproperty float x\nproperty float y\n"
      "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
      MeshFormat::Auto, limits);
  ASSERT_FALSE(tooMany.ok());
  EXPECT_EQ(tooMany.error().code, ErrorCode::TooLarge);
  std::string stl(84, '\0');
  stl[80] = '\x10';  // 16 triangles announced, none there
  auto truncated = parsePolygonSoup(stl, MeshFormat::Stl);
  ASSERT_FALSE(truncated.ok());
  EXPECT_EQ(truncated.error().code, ErrorCode::Parse);
  EXPECT_NE(truncated.error().message.find("16 triangles"), std::string::npos) << truncated.error().message;
}

}  // namespace
}  // namespace straightest
