// The OBJ reader: every supported form on valid files (corner forms, negative and forward indices,
// line endings, exact numbers), its own rules (strict numbers, the caps, the order of errors), and
// the inputs fuzzing found. The malformed corpus is checked in malformed_input_test.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::dataPath;
using testing::loadGood;

Error objError(const std::string& text, const BuildLimits& limits = {}) {
  auto soup = parsePolygonSoup(text, MeshFormat::Obj, limits);
  EXPECT_FALSE(soup.ok()) << "accepted:\n" << text;
  return soup.ok() ? Error{ErrorCode::InvalidArgument, "(accepted)"} : soup.error();
}

PolygonSoup objSoup(const std::string& text) {
  auto soup = parsePolygonSoup(text, MeshFormat::Obj);
  if (!soup) throw std::runtime_error("rejected: " + soup.error().message);
  return std::move(soup).value();
}

TEST(ObjReader, QuadsAreTriangulatedIntoTwoTrianglesEach) {
  const TriMesh mesh = loadGood("good/quad_grid.obj");
  EXPECT_EQ(mesh.numVertices(), 9);
  EXPECT_EQ(mesh.numFaces(), 8);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 1);  // a disk
  ASSERT_FALSE(mesh.summary().problems.empty());
  EXPECT_NE(mesh.summary().problems[0].find("4 polygons"), std::string::npos);
  double area = 0;
  for (int f = 0; f < mesh.numFaces(); ++f) area += mesh.faceArea(f);
  EXPECT_NEAR(area, 4.0, 1e-12);  // the triangles tile the 2 x 2 square exactly
}

TEST(ObjReader, AcceptsVertexTextureNormalCorners) {
  const TriMesh mesh = loadGood("good/vt_vn.obj");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(mesh.triangle(1), (Triangle{0, 2, 3}));
}

TEST(ObjReader, ResolvesNegativeIndicesRelativeToVerticesSoFar) {
  const TriMesh mesh = loadGood("good/negative_indices.obj");
  ASSERT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(mesh.triangle(0), (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangle(1), (Triangle{1, 3, 2}));  // -3,-1,-2 after the 4th vertex
}

TEST(ObjReader, FacesMayReferToVerticesDefinedLaterAndKeepTheirPlace) {
  // Face 1, a quad, uses vertices 4 and 5 before they are defined; its two triangles still come
  // between face 0's and face 2's, and the quad is split inside its outline.
  const PolygonSoup soup = objSoup(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "f 1 2 3\n"
      "f 2 4 5 3\n"
      "v 1 1 0\nv 0.5 1.5 0\n"
      "f 3 5 1\n");
  ASSERT_EQ(soup.triangles.size(), 4u);
  EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(soup.triangles[3], (Triangle{2, 4, 0}));
  EXPECT_EQ(soup.polygonsTriangulated, 1);
  double area = 0;
  for (int k : {1, 2}) {
    const Triangle& t = soup.triangles[k];
    for (int32_t v : t) EXPECT_TRUE(v == 1 || v == 2 || v == 3 || v == 4) << v;
    const Vec3 n = cross(soup.positions[t[1]] - soup.positions[t[0]], soup.positions[t[2]] - soup.positions[t[0]]);
    EXPECT_GT(n.z, 0) << "triangle " << k << " lost the quad's winding";
    area += n.z / 2;
  }
  EXPECT_NEAR(area, 0.75, 1e-15);  // the quad (1,0) (1,1) (0.5,1.5) (0,1)
}

TEST(ObjReader, ReadsCrlfLineEndings) {
  const TriMesh mesh = loadGood("good/crlf.obj");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 2);
  EXPECT_DOUBLE_EQ(mesh.position(3).y, 1.0);
}

TEST(ObjReader, ReadsOldMacLineEndings) {
  // A lone CR ends a line; CR LF is one line end, not two (the line numbers say so).
  const PolygonSoup soup = objSoup("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  EXPECT_EQ(soup.positions.size(), 3u);
  EXPECT_EQ(soup.triangles.size(), 1u);
  EXPECT_NE(objError("v 0 0 0\r\nv 1 0 0\rv 0 1\n").message.find("line 3:"), std::string::npos);
}

TEST(ObjReader, LoadsFromAnInMemoryBufferLikeFromAFile) {
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(ObjReader, CoordinatesAreCorrectlyRoundedDecimals) {
  const PolygonSoup soup = objSoup(
      "v 0.1 0.2 0.3\n"
      "v 9007199254740993 2.2250738585072011e-308 1.7976931348623157e308\n"
      "v +1.5 -.5 1.\n"
      "v 1e-5 0 0 1.0 # a w and a comment\n");
  EXPECT_EQ(soup.positions[0].x, 0.1);
  EXPECT_EQ(soup.positions[0].y, 0.2);
  EXPECT_EQ(soup.positions[0].z, 0.3);
  EXPECT_EQ(soup.positions[1].x, 9007199254740992.0);  // 2^53 + 1 rounds to even
  EXPECT_EQ(soup.positions[1].y, 2.2250738585072011e-308);
  EXPECT_EQ(soup.positions[1].z, 1.7976931348623157e308);
  EXPECT_EQ(soup.positions[2].x, 1.5);
  EXPECT_EQ(soup.positions[2].y, -0.5);
  EXPECT_EQ(soup.positions[2].z, 1.0);
  EXPECT_EQ(soup.positions[3].x, 1e-5);
}

TEST(ObjReader, HexadecimalCoordinateIsRejectedNotReadAsZero) {
  // Found by fuzz_obj: strtod reads 0x1p3 as 8, tinyobjloader read it as 0 — a silent wrong answer.
  auto mesh = loadMeshFile(dataPath("../fuzz/regressions/fuzz_obj/hex_float_read_as_zero.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Parse);
  EXPECT_NE(mesh.error().message.find("line 3"), std::string::npos) << mesh.error().message;
}

TEST(ObjReader, ExponentsOfMoreThanFourDigitsAreRefusedAnywhereOnAVertexLine) {
  for (const char* line : {"v 1e12345 0 0\n", "v 0 0 0 1e-00001\n", "v 0 0 0 # 2.E+99999\n"}) {
    const Error e = objError(std::string("v 0 0 0\nv 1 0 0\n") + line + "f 1 2 3\n");
    EXPECT_EQ(e.code, ErrorCode::Parse) << line;
    EXPECT_EQ(e.message, "line 3: a number has an exponent with more than 4 digits") << line;
  }
  EXPECT_EQ(objSoup("v 0 0 0\nv 1 0 0\nv 0 1e-0001 1e+0300\nf 1 2 3\n").positions[2].z, 1e300);
}

TEST(ObjReader, InputsFoundByFuzzingGiveTheirErrors) {
  const std::pair<const char*, ErrorCode> cases[] = {
      {"index_wraps_modulo_2_32.obj", ErrorCode::IndexOutOfRange},  // atoi wrapped 4294967299 to 3
      {"int64_overflow_index.obj", ErrorCode::Parse},               // 19 digits
      {"lone_cr_hides_nan.obj", ErrorCode::NonFinite},              // lone CR line breaks; nan is seen
      {"tinyobj_exponent_overflow.obj", ErrorCode::Parse},          // 1e-2147483648
  };
  for (const auto& [file, code] : cases) {
    auto mesh = loadMeshFile(dataPath(std::string("../fuzz/regressions/fuzz_obj/") + file));
    ASSERT_FALSE(mesh.ok()) << file;
    EXPECT_EQ(mesh.error().code, code) << file << ": " << mesh.error().message;
  }
  // 0e500 is zero (tinyobjloader computed 0 × 10^500 = NaN).
  const TriMesh zero = loadGood("../fuzz/regressions/fuzz_obj/zero_with_huge_exponent_reads_nan.obj");
  EXPECT_EQ(zero.position(0).x, 0.0);
}

TEST(ObjReader, TenMegabyteLineIsRejectedQuicklyNotHung) {
  // One "v" line with a 10 MB coordinate token, and one 10 MB comment line before a valid mesh.
  std::string huge = "v " + std::string(10'000'000, '1') + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  auto mesh = loadMesh(huge);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Parse);
  std::string comment = "# " + std::string(10'000'000, 'x') + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_TRUE(loadMesh(comment).ok());
}

TEST(ObjReader, AForwardIndexPastTheLastVertexNamesItsLine) {
  const Error e = objError("v 0 0 0\nf 1 2 4\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
  EXPECT_EQ(e.message, "line 2: face 0 refers to vertex 4 (1-based), but the file has 3 vertices");
}

TEST(ObjReader, AVertexIsNamedAsTheFileCountsIt) {
  EXPECT_EQ(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nf 1 2 3\n").message,
            "line 4: vertex 4 (1-based) has a non-finite coordinate 'nan'");
  EXPECT_EQ(objError("v 0 0 0\nv 1 0\n").message, "line 2: vertex 2 (1-based) has 2 coordinates, expected at least 3");
}

TEST(ObjReader, ErrorsComeInFileOrderLineErrorsFirst) {
  // A malformed line anywhere wins over a missing vertex, which is only known at the end of the file.
  const Error e = objError("f 1 2 9\nv 0 0 0\nv 1 0 0\nv nan 0 0\n");
  EXPECT_EQ(e.code, ErrorCode::NonFinite);
  EXPECT_NE(e.message.find("line 4"), std::string::npos) << e.message;
}

TEST(ObjReader, CapsCountVerticesAndTrianglesAndTheFirstFailingFaceDecides) {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  EXPECT_EQ(objError(square + "f 1 2 3\n", BuildLimits{3, 10}).message, "file has 4 vertices, over the limit of 3");
  // A quad is two triangles: with the triangle, three, over a cap of two.
  const Error overCap = objError(square + "f 1 2 3 4\nf 1 3 4\n", BuildLimits{10, 2});
  EXPECT_EQ(overCap.code, ErrorCode::TooLarge);
  EXPECT_EQ(overCap.message, "file has more than 2 faces");
  // Face 0 refers to a missing vertex, face 1 passes the cap: face 0's error.
  EXPECT_EQ(objError(square + "f 1 2 7\nf 1 2 3 4\n", BuildLimits{10, 2}).code, ErrorCode::IndexOutOfRange);
  // Face 0 passes the cap, face 1 refers to a missing vertex: the cap.
  EXPECT_EQ(objError(square + "f 1 2 3 4\nf 1 3 4\nf 1 2 7\n", BuildLimits{10, 2}).code, ErrorCode::TooLarge);
}

TEST(ObjReader, StatementsOtherThanVAndFAreSkippedWhateverTheyHold) {
  // A "vw" joint id of 3e9 and a "vt" exponent of 99999 (a fuzzing finding: they once reached a
  // reader that overflowed on them) are not geometry: the mesh is the v and f lines.
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 3e9 1\nvt 0 1e-99999\nf 1 2 3\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(ObjReader, KeywordsAreDelimitedBySpaceOrTabOnly) {
  // A vertical tab before or after "v"/"f" does not make a statement: only space and tab end a keyword.
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n\v\vf 2 4 3\nv\v5 5 5\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numVertices(), 4);
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

}  // namespace
}  // namespace straightest
