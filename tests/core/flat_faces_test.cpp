// The shooting walk's flat face records (private: core/src/flat_faces.hpp): each face laid flat keeps its
// edge lengths, and FlatFace::at picks a corner with the same bits as the products by 0 and 1 it replaced
// (one · length + two · corner.x, two · corner.y), also where a coordinate difference is −0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "straightest/mesh/flat_faces.hpp"
#include "straightest/mesh/samples.hpp"

namespace straightest {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectRecordsFaithful(const TriMesh& mesh) {
  const std::vector<FlatFace> faces = flatFaces(mesh);
  ASSERT_EQ(faces.size(), static_cast<size_t>(mesh.numFaces()));
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const FlatFace& r = faces[f];
    EXPECT_FALSE(std::signbit(r.corner.x) && r.corner.x == 0) << "face " << f << ": corner.x is -0";
    for (int k = 0; k < 3; ++k) {
      const double one = k == 1, two = k == 2;
      const Vec2 c = r.at(k);
      EXPECT_TRUE(sameBits(c.x, one * r.length + two * r.corner.x)) << "face " << f << " corner " << k;
      EXPECT_TRUE(sameBits(c.y, two * r.corner.y)) << "face " << f << " corner " << k;
      if (mesh.isDegenerateFace(f)) continue;
      // The flat edge from corner k to corner k + 1 is as long as the 3D one.
      const Triangle& t = mesh.triangle(f);
      const double flat = std::hypot(r.at((k + 1) % 3).x - c.x, r.at((k + 1) % 3).y - c.y);
      const double real = norm(mesh.position(t[(k + 1) % 3]) - mesh.position(t[k]));
      EXPECT_NEAR(flat, real, 1e-12 * real) << "face " << f << " edge " << k;
    }
  }
}

TEST(FlatFaces, HeightFieldRecordsKeepEdgeLengthsAndPickCornersExactly) { expectRecordsFaithful(makeHeightField(20)); }

TEST(FlatFaces, NegativeZeroCoordinatesGiveTheSameCorners) {
  // Right angles at corner 0 with −0 coordinates: corner 2's x, w · e / |e|, is −0 before it is stored.
  std::vector<Vec3> positions{{0, 0, 0}, {1, -0.0, 0}, {-0.0, 1, -0.0}, {1, 1, 0}};
  std::vector<Triangle> triangles{{0, 1, 2}, {1, 3, 2}};
  const Vec3 e = positions[1] - positions[0], w = positions[2] - positions[0];
  ASSERT_TRUE(dot(w, e) == 0 && std::signbit(dot(w, e)));  // the case this test is about
  auto mesh = TriMesh::build(positions, triangles);
  ASSERT_TRUE(mesh) << mesh.error().message;
  expectRecordsFaithful(mesh.value());
  const FlatFace r = flatFaces(mesh.value())[0];
  EXPECT_EQ(r.length, 1.0);
  EXPECT_EQ(r.corner.y, 1.0);
  EXPECT_FALSE(std::signbit(r.corner.x));
}

}  // namespace
}  // namespace straightest
