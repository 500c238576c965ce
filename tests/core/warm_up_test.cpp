// The warm-up's estimates (warm_up.hpp): how much heap a load touches ahead of the first
// parameterization, from a vertex count or from the vertices a mesh file holds.
#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/api/warm_up.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"

namespace straightest {
namespace {

TEST(WarmUpEstimates, TheHeapGrowsWithTheVertexCountAndNothingIsTouchedForNoVertices) {
  EXPECT_EQ(parameterizationHeapBytes(0), 0u);
  EXPECT_EQ(parameterizationHeapBytes(-5), 0u);
  const std::size_t million = parameterizationHeapBytes(1000000);
  // Measured at 1M vertices: 314 MB natively, 256 MB in WebAssembly; the estimate stays below.
  EXPECT_GE(million, std::size_t{200} << 20);
  EXPECT_LE(million, std::size_t{314} << 20);
  EXPECT_EQ(parameterizationHeapBytes(2000000), 2 * million);
  // A header's count can be anything: the estimate saturates instead of overflowing (32-bit size_t too).
  EXPECT_EQ(parameterizationHeapBytes(std::numeric_limits<int64_t>::max()), std::numeric_limits<std::size_t>::max());
}

TEST(WarmUpEstimates, ACountGivesUpWithNothingOnceTheLoadHasStopped) {
  std::string obj;
  for (int i = 0; i < 200000; ++i) obj += "v 0 0 0\n";  // 1.6 MB: more than one look at stop
  std::atomic<bool> stop{false};
  EXPECT_EQ(verticesInFile(obj, MeshFormat::Obj, &stop), 200000);
  std::string plyWithoutEnd = "ply\nformat ascii 1.0\n";
  for (int i = 0; i < 10000; ++i) plyWithoutEnd += "comment no end_header yet\n";
  EXPECT_EQ(verticesInFile(plyWithoutEnd + "element vertex 7\n", MeshFormat::Ply, &stop), 7);
  stop = true;
  EXPECT_EQ(verticesInFile(obj, MeshFormat::Obj, &stop), 0);
  EXPECT_EQ(verticesInFile(plyWithoutEnd + "element vertex 7\n", MeshFormat::Ply, &stop), 0);
}

TEST(WarmUpEstimates, AMeshFilesVertexCountComesFromItsHeaderOrItsVertexLinesWithoutParsing) {
  const TriMesh mesh = makeHeightField(40);
  std::string off = "# a comment\n\nOFF\n" + std::to_string(mesh.numVertices()) + " " +
                    std::to_string(mesh.numFaces()) + " 0\n";
  for (const Vec3& p : mesh.positions())
    off += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  for (const auto& t : mesh.triangles())
    off += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
  EXPECT_EQ(verticesInFile(off, MeshFormat::Off), mesh.numVertices());
  EXPECT_EQ(verticesInFile(off, MeshFormat::Auto), mesh.numVertices());  // detected as OFF
  EXPECT_EQ(verticesInFile("OFF 8 6 0\n", MeshFormat::Off), 8);          // counts on the keyword's line
  // An OBJ with texture coordinates and normals: only its v lines count (vt, vn and f do not).
  std::vector<Vec2> uv(static_cast<size_t>(mesh.numVertices()), Vec2{0.5, 0.5});
  const std::string obj = writeObj(mesh, &uv) + "vn 0 0 1\n  v 1 2 3\n";
  EXPECT_EQ(verticesInFile(obj, MeshFormat::Obj), mesh.numVertices() + 1);
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 12\nproperty float x\nelement face 20\nend_header\n";
  EXPECT_EQ(verticesInFile(ply, MeshFormat::Auto), 12);
  // No count: STL repeats corners; an OFF header without a number.
  EXPECT_EQ(verticesInFile("solid x\nendsolid x\n", MeshFormat::Auto), 0);
  EXPECT_EQ(verticesInFile(off, MeshFormat::Stl), 0);
  EXPECT_EQ(verticesInFile("OFF\nBINARY\n", MeshFormat::Off), 0);
}

}  // namespace
}  // namespace straightest
