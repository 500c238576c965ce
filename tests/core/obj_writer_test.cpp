// The OBJ writer: what it writes reads back as the same mesh, exactly; with uv, one `vt` per vertex
// in vertex order and v/vt corners.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "straightest/mesh_io.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

size_t countLinesStartingWith(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  size_t count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind(prefix, 0) == 0;
  return count;
}

void expectSameMesh(const TriMesh& a, const TriMesh& b) {
  ASSERT_EQ(a.numVertices(), b.numVertices());
  EXPECT_EQ(a.triangles(), b.triangles());
  for (int32_t v = 0; v < a.numVertices(); ++v) {
    EXPECT_EQ(a.position(v).x, b.position(v).x) << v;  // 17 significant digits: the same doubles
    EXPECT_EQ(a.position(v).y, b.position(v).y) << v;
    EXPECT_EQ(a.position(v).z, b.position(v).z) << v;
  }
}

TEST(ObjWriter, WhatItWritesReadsBackAsTheSameMeshExactly) {
  const TriMesh mesh = testing::icosphere(1);
  const std::string text = writeObj(mesh);
  EXPECT_EQ(countLinesStartingWith(text, "v "), static_cast<size_t>(mesh.numVertices()));
  EXPECT_EQ(countLinesStartingWith(text, "f "), static_cast<size_t>(mesh.numFaces()));
  EXPECT_EQ(countLinesStartingWith(text, "vt "), 0u);
  auto again = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(again.ok()) << again.error().message;
  expectSameMesh(mesh, again.value());
}

TEST(ObjWriter, WritesOneTextureCoordinatePerVertexAndVSlashVtCorners) {
  const TriMesh mesh = testing::flatGrid(4, testing::GridPattern::Regular);
  std::vector<Vec2> uv;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) uv.push_back({0.1 * v, 1.0 / 3.0});
  const std::string text = writeObj(mesh, &uv);
  EXPECT_EQ(countLinesStartingWith(text, "vt "), uv.size());
  const Triangle& t = mesh.triangle(0);
  const std::string corners = " " + std::to_string(t[0] + 1) + "/" + std::to_string(t[0] + 1) + " " +
                              std::to_string(t[1] + 1) + "/" + std::to_string(t[1] + 1);
  EXPECT_NE(text.find("\nf" + corners), std::string::npos) << "face 0 should be written as v/vt corners";
  EXPECT_NE(text.find("vt 0.30000000000000004 0.33333333333333331\n"), std::string::npos);  // vertex 3's uv
  auto again = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(again.ok()) << again.error().message;
  expectSameMesh(mesh, again.value());
}

}  // namespace
}  // namespace straightest
