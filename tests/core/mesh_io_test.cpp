// Choosing the format (from a name, from the bytes) and reading files; the readers themselves are
// specified in obj_reader_test and off_reader_test.
#include <string>

#include <gtest/gtest.h>

#include "straightest/io/mesh_io.hpp"
#include "test_util.hpp"

namespace straightest {
namespace {

TEST(FormatDetection, RecognizesOffByItsHeaderAndObjOtherwise) {
  EXPECT_TRUE(loadMesh("# comment\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").ok());
  EXPECT_TRUE(loadMesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").ok());
  // The same OFF bytes read as OBJ are not a mesh: the format asked for wins over the content.
  auto forced = loadMesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Obj);
  ASSERT_FALSE(forced.ok());
  EXPECT_EQ(forced.error().code, ErrorCode::UnsupportedFormat);
}

TEST(FormatDetection, TextWithoutMeshStatementsIsUnsupported) {
  auto mesh = loadMesh("hello world\nthis is not a mesh\n");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::UnsupportedFormat);
}

TEST(FormatNames, AreCaseInsensitiveAndUnknownOnesAreRefused) {
  EXPECT_EQ(parseMeshFormat("OBJ").value(), MeshFormat::Obj);
  EXPECT_EQ(parseMeshFormat("off").value(), MeshFormat::Off);
  EXPECT_EQ(parseMeshFormat("Auto").value(), MeshFormat::Auto);
  EXPECT_EQ(parseMeshFormat("").value(), MeshFormat::Auto);
  EXPECT_EQ(parseMeshFormat("PLY").value(), MeshFormat::Ply);
  EXPECT_EQ(parseMeshFormat("stl").value(), MeshFormat::Stl);
  auto bad = parseMeshFormat("gltf");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::UnsupportedFormat);
  EXPECT_NE(bad.error().message.find("'gltf'"), std::string::npos) << bad.error().message;
}

TEST(FormatNames, FileNameExtensionChoosesTheFormatInAnyCase) {
  EXPECT_EQ(meshFormatFromFileName("mesh.obj"), MeshFormat::Obj);
  EXPECT_EQ(meshFormatFromFileName("dir.off/Mesh.OBJ"), MeshFormat::Obj);
  EXPECT_EQ(meshFormatFromFileName("/tmp/scan.Off"), MeshFormat::Off);
  EXPECT_EQ(meshFormatFromFileName("C:\\meshes\\Lion.OFF"), MeshFormat::Off);
  EXPECT_EQ(meshFormatFromFileName("dir.obj/mesh"), MeshFormat::Auto);  // a directory's dot is no extension
  EXPECT_EQ(meshFormatFromFileName(".off"), MeshFormat::Off);
  EXPECT_EQ(meshFormatFromFileName("mesh.ply"), MeshFormat::Ply);
  EXPECT_EQ(meshFormatFromFileName("Part.STL"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatFromFileName("scene.glb"), MeshFormat::Auto);
  EXPECT_EQ(meshFormatFromFileName("mesh.obj.gz"), MeshFormat::Auto);
  EXPECT_EQ(meshFormatFromFileName("obj"), MeshFormat::Auto);
  EXPECT_EQ(meshFormatFromFileName(""), MeshFormat::Auto);
}

TEST(MeshFiles, LoadLikeTheirBytesWithTheFormatOfTheirName) {
  const std::string path = testing::dataPath("good/quad_grid.obj");
  const TriMesh fromFile = testing::loadGood("good/quad_grid.obj");
  auto fromBytes = loadMesh(testing::readFile(path), meshFormatFromFileName(path));
  ASSERT_TRUE(fromBytes.ok()) << fromBytes.error().message;
  EXPECT_EQ(fromBytes.value().triangles(), fromFile.triangles());
  ASSERT_EQ(fromBytes.value().numVertices(), fromFile.numVertices());
  for (int32_t v = 0; v < fromFile.numVertices(); ++v)
    EXPECT_EQ(fromBytes.value().position(v).x, fromFile.position(v).x);
}

TEST(MeshFiles, MissingFileIsAnIoErrorNamingThePath) {
  auto mesh = loadMeshFile(testing::dataPath("does/not/exist.obj"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Io);
  EXPECT_NE(mesh.error().message.find("does/not/exist.obj"), std::string::npos) << mesh.error().message;
}

TEST(MeshFiles, ADirectoryIsAnIoErrorNotAFileTooLarge) {
  auto mesh = loadMeshFile(testing::dataPath("bad"));
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::Io) << mesh.error().message;
  EXPECT_NE(mesh.error().message.find("directory"), std::string::npos) << mesh.error().message;
}

}  // namespace
}  // namespace straightest
