// Loader behaviour: every supported OBJ/OFF form on valid files, and a typed, located error for
// every malformed one.
#include <string>

#include <gtest/gtest.h>

#include "straightest/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

using testing::dataPath;
using testing::loadGood;

Error loadError(const std::string& relative) {
  auto mesh = loadMeshFile(dataPath(relative));
  EXPECT_FALSE(mesh.ok()) << relative << " should have been rejected";
  return mesh.ok() ? Error{ErrorCode::InvalidArgument, "(loaded)"} : mesh.error();
}

TEST(ObjLoader, QuadsAreTriangulatedIntoTwoTrianglesEach) {
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

TEST(ObjLoader, AcceptsVertexTextureNormalCorners) {
  const TriMesh mesh = loadGood("good/vt_vn.obj");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(mesh.triangle(1), (Triangle{0, 2, 3}));
}

TEST(ObjLoader, ResolvesNegativeIndicesRelativeToVerticesSoFar) {
  const TriMesh mesh = loadGood("good/negative_indices.obj");
  ASSERT_EQ(mesh.numFaces(), 2);
  EXPECT_EQ(mesh.triangle(0), (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangle(1), (Triangle{1, 3, 2}));  // -3,-1,-2 after the 4th vertex
}

TEST(ObjLoader, ReadsCrlfLineEndings) {
  const TriMesh mesh = loadGood("good/crlf.obj");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 2);
  EXPECT_DOUBLE_EQ(mesh.position(3).y, 1.0);
}

TEST(ObjLoader, LoadsFromAnInMemoryBufferLikeFromAFile) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  auto mesh = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(ObjLoader, StatementsOtherThanVAndFNeverReachTinyobjloader) {
  // tinyobjloader converted the joint id 3e9 of a "vw" line to int (undefined behaviour; found by fuzzing).
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 3e9 1\nvt 0 1e-99999\nf 1 2 3\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(ObjLoader, KeywordsAreDelimitedBySpaceOrTabOnly) {
  // A vertical tab before or after "v"/"f" does not make a statement (as in tinyobjloader); our reader
  // and tinyobjloader read the same lines.
  auto mesh = loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n\v\vf 2 4 3\nv\v5 5 5\n", MeshFormat::Obj);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numVertices(), 4);
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(OffLoader, ToleratesCommentsAndBlankLines) {
  const TriMesh mesh = loadGood("good/tetrahedron.off");
  EXPECT_EQ(mesh.numVertices(), 4);
  EXPECT_EQ(mesh.numFaces(), 4);
}

TEST(OffLoader, AcceptsCountsOnTheHeaderLine) {
  auto mesh = loadMesh("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Auto);
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  EXPECT_EQ(mesh.value().numFaces(), 1);
}

TEST(OffLoader, TriangulatesANonConvexPolygonInsideItsOutline) {
  // An L-shaped hexagon: a fan from vertex 0 would cover area outside the polygon; ear clipping does not.
  const std::string text = "OFF\n6 1 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 0 1 2 3 4 5\n";
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

TEST(OffLoader, CountsPolygonsAsFacesWhateverTheirTriangleCount) {
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

TEST(OffLoader, AcceptsColouredAndNormalVariants) {
  auto coff = loadMesh("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
  ASSERT_TRUE(coff.ok()) << coff.error().message;
  EXPECT_EQ(coff.value().position(1).x, 1.0);
  auto noff = loadMesh("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(noff.ok()) << noff.error().message;
  EXPECT_FALSE(loadMesh("OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n").ok());  // plain OFF stays strict
}

TEST(FormatDetection, RecognizesOffByItsHeaderAndObjOtherwise) {
  EXPECT_TRUE(loadMesh("# comment\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").ok());
  EXPECT_TRUE(loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").ok());
  auto bad = parseMeshFormat("stl");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::UnsupportedFormat);
}

TEST(MalformedInput, EmptyFileIsEmpty) { EXPECT_EQ(loadError("bad/empty.obj").code, ErrorCode::Empty); }

TEST(MalformedInput, BinaryGarbageIsUnsupported) {
  EXPECT_EQ(loadError("bad/garbage.bin").code, ErrorCode::UnsupportedFormat);
}

TEST(MalformedInput, TextWithoutMeshStatementsIsUnsupported) {
  auto mesh = loadMesh("hello world\nthis is not a mesh\n");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::UnsupportedFormat);
}

TEST(MalformedInput, NanCoordinateIsReportedWithItsLine) {
  const Error e = loadError("bad/nan.obj");
  EXPECT_EQ(e.code, ErrorCode::NonFinite);
  EXPECT_NE(e.message.find("line 2"), std::string::npos) << e.message;
}

TEST(MalformedInput, InfCoordinateInOffIsReportedWithItsLine) {
  const Error e = loadError("bad/inf.off");
  EXPECT_EQ(e.code, ErrorCode::NonFinite);
  EXPECT_NE(e.message.find("line 4"), std::string::npos) << e.message;
}

TEST(MalformedInput, IndexOutOfRangeNamesLineAndIndex) {
  const Error e = loadError("bad/index_out_of_range.obj");
  EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
  EXPECT_NE(e.message.find("line 4"), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("9"), std::string::npos) << e.message;
}

TEST(MalformedInput, ZeroIndexIsOutOfRangeInObj) {
  const Error e = loadError("bad/zero_index.obj");
  EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
  EXPECT_NE(e.message.find("line 4"), std::string::npos) << e.message;
}

TEST(MalformedInput, TwoVertexFaceIsInvalid) {
  const Error e = loadError("bad/two_vertex_face.obj");
  EXPECT_EQ(e.code, ErrorCode::InvalidFace);
  EXPECT_NE(e.message.find("line 5"), std::string::npos) << e.message;
}

TEST(MalformedInput, OffHeaderClaimingATrillionVerticesFailsWithoutAllocating) {
  const Error e = loadError("bad/off_header_lies.off");
  EXPECT_EQ(e.code, ErrorCode::TooLarge) << e.message;
  // Below the caps, a header that claims more than the bytes that follow is a parse error.
  auto lying = loadMesh("OFF\n1000000 1 0\n0 0 0\n");
  ASSERT_FALSE(lying.ok());
  EXPECT_EQ(lying.error().code, ErrorCode::Parse);
  EXPECT_NE(lying.error().message.find("bytes follow"), std::string::npos) << lying.error().message;
}

TEST(MalformedInput, TruncatedOffSaysHowFarItGot) {
  const Error e = loadError("bad/off_truncated.off");
  EXPECT_EQ(e.code, ErrorCode::Parse);
  EXPECT_NE(e.message.find("1 of 2 faces"), std::string::npos) << e.message;
}

TEST(MalformedInput, NonNumericOffCoordinateIsAParseError) {
  const Error e = loadError("bad/off_bad_token.off");
  EXPECT_EQ(e.code, ErrorCode::Parse);
  EXPECT_NE(e.message.find("line 4"), std::string::npos) << e.message;
}

TEST(MalformedInput, TenMegabyteLineIsRejectedQuicklyNotHung) {
  // One "v" line with a 10 MB coordinate token, and one 10 MB comment line before a valid mesh.
  std::string huge = "v " + std::string(10'000'000, '1') + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  auto mesh = loadMesh(huge);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Parse);
  std::string comment = "# " + std::string(10'000'000, 'x') + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_TRUE(loadMesh(comment).ok());
}

TEST(MalformedInput, HexadecimalObjCoordinateIsRejectedNotReadAsZero) {
  // Found by fuzz_obj: strtod reads 0x1p3 as 8, tinyobjloader as 0 — a silent wrong answer.
  auto mesh = loadMeshFile(dataPath("../fuzz/regressions/fuzz_obj/hex_float_read_as_zero.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Parse);
  EXPECT_NE(mesh.error().message.find("line 3"), std::string::npos) << mesh.error().message;
  EXPECT_TRUE(loadMesh("v 0 0 0\nv 1.5e+0 0 0\nv -.5 1. 0\nf 1 2 3\n").ok());  // plain decimals still read
}

TEST(MalformedInput, FuzzFoundObjDisagreementsAreErrorsNotSilentlyDifferentMeshes) {
  // Each of these was read differently by tinyobjloader and by a careful reader (found by fuzz_obj).
  const std::pair<const char*, ErrorCode> cases[] = {
      {"index_wraps_modulo_2_32.obj", ErrorCode::IndexOutOfRange},  // atoi wrapped 4294967299 to 3
      {"int64_overflow_index.obj", ErrorCode::Parse},               // 19 digits
      {"lone_cr_hides_nan.obj", ErrorCode::NonFinite},              // lone CR line breaks; nan is seen
  };
  for (const auto& [file, code] : cases) {
    auto mesh = loadMeshFile(dataPath(std::string("../fuzz/regressions/fuzz_obj/") + file));
    ASSERT_FALSE(mesh.ok()) << file;
    EXPECT_EQ(mesh.error().code, code) << file << ": " << mesh.error().message;
  }
  // 1e-2147483648: tinyobjloader's exponent arithmetic overflows, so such lines are refused first.
  auto tiny = loadMeshFile(dataPath("../fuzz/regressions/fuzz_obj/tinyobj_exponent_overflow.obj"));
  ASSERT_FALSE(tiny.ok());
  EXPECT_EQ(tiny.error().code, ErrorCode::Parse);
  auto off = loadMeshFile(dataPath("../fuzz/regressions/fuzz_off/int64_overflow_count.off"));
  ASSERT_FALSE(off.ok());
  EXPECT_EQ(off.error().code, ErrorCode::Parse) << off.error().message;
  // Old Mac line endings (lone CR) are lines, like in tinyobjloader.
  EXPECT_TRUE(loadMesh("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", MeshFormat::Obj).ok());
}

TEST(MalformedInput, MissingFileIsAnIoError) {
  EXPECT_EQ(loadError("does/not/exist.obj").code, ErrorCode::Io);
}

}  // namespace
}  // namespace straightest
