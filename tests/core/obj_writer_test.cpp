// The OBJ writer: what it writes reads back as the same mesh, exactly; with uv, one `vt` per vertex
// in vertex order and v/vt corners; the same text whatever the thread count.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "straightest/base/threads.hpp"
#include "straightest/io/mesh_io.hpp"
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
  // Vertex 3's uv in the fewest digits that read back exactly: 0.1 × 3 needs 17, 1/3 needs 16.
  EXPECT_NE(text.find("vt 0.30000000000000004 0.3333333333333333\n"), std::string::npos);
  auto again = loadMesh(text, MeshFormat::Obj);
  ASSERT_TRUE(again.ok()) << again.error().message;
  expectSameMesh(mesh, again.value());
}

TEST(ObjWriter, WritesTheSameTextOnOneAndSeveralThreads) {
  // 40k vertices and 80k faces: several runs of lines, formatted by different threads.
  const TriMesh mesh = testing::flatGrid(200, testing::GridPattern::Jittered);
  std::vector<Vec2> uv, cornerUv;
  for (int32_t v = 0; v < mesh.numVertices(); ++v) uv.push_back({std::sin(0.37 * v), 1.0 / (v + 3)});
  for (const Triangle& t : mesh.triangles())
    for (int k = 0; k < 3; ++k) cornerUv.push_back(uv[t[k]]);
  std::vector<std::string> texts;
  for (int threads : {1, 3}) {
    setThreadCount(threads);
    texts.push_back(writeObj(mesh, &uv) + writeObjWithCornerUv(mesh, cornerUv));
  }
  setThreadCount(0);
  EXPECT_EQ(texts[0], texts[1]);
  const std::string plain = writeObj(mesh, &uv);
  auto again = loadMesh(plain, MeshFormat::Obj);
  ASSERT_TRUE(again.ok()) << again.error().message;
  expectSameMesh(mesh, again.value());
  EXPECT_EQ(countLinesStartingWith(plain, "vt "), uv.size());
}

TEST(ObjWriter, WritesTheShortestDigitsThatReadBackAsTheSameDouble) {
  // A triangle whose coordinates are short decimals: written as such, not padded to 17 digits.
  std::vector<Vec3> positions = {{0.3346, -2.5, 1e-7}, {1, 0, 0}, {0, 1, 123456.789}};
  auto mesh = TriMesh::build(positions, {{0, 1, 2}});
  ASSERT_TRUE(mesh.ok()) << mesh.error().message;
  const std::string text = writeObj(mesh.value());
  EXPECT_NE(text.find("\nv 0.3346 -2.5 1e-07\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nv 0 1 123456.789\n"), std::string::npos) << text;

  // Random doubles of every magnitude (bit patterns) read back bit for bit.
  std::mt19937_64 random(16);
  std::vector<Vec3> many;
  std::vector<Vec2> uv;
  while (many.size() < 3000) {
    double c[3];
    for (double& x : c) {
      const uint64_t bits = random();
      std::memcpy(&x, &bits, sizeof x);
      if (!std::isfinite(x) || std::abs(x) > 1e40 || std::abs(x) < 1e-40)
        x = std::ldexp(static_cast<double>(bits >> 11), -53) - 0.5;
    }
    many.push_back({c[0], c[1], c[2]});
    uv.push_back({c[1], c[2]});
  }
  std::vector<Triangle> triangles;
  for (int32_t i = 0; i + 2 < static_cast<int32_t>(many.size()); i += 3) triangles.push_back({i, i + 1, i + 2});
  auto scattered = TriMesh::build(many, triangles);
  ASSERT_TRUE(scattered.ok()) << scattered.error().message;
  const std::string written = writeObj(scattered.value(), &uv);
  auto again = loadMesh(written, MeshFormat::Obj);
  ASSERT_TRUE(again.ok()) << again.error().message;
  expectSameMesh(scattered.value(), again.value());
  // The uv too (read here by strtod, which rounds correctly as the OBJ reader does).
  std::istringstream in(written);
  size_t k = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("vt ", 0) != 0) continue;
    char* end = nullptr;
    const double u = std::strtod(line.c_str() + 3, &end), v = std::strtod(end, nullptr);
    ASSERT_LT(k, uv.size());
    EXPECT_EQ(u, uv[k].x) << line;
    EXPECT_EQ(v, uv[k].y) << line;
    EXPECT_LE(line.size(), 3 + 2 * 24u) << "more than 17 digits?";
    ++k;
  }
  EXPECT_EQ(k, uv.size());
}

}  // namespace
}  // namespace straightest
