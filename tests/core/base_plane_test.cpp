// The base plane at a source and the cutting plane toward a destination: the normal is the paper's mean of
// the virtual faces' normals however short, faces the surface's side, falls back (and says so) only where that
// mean is numerically zero or the mesh is closed, and there is no plane toward a point along the normal.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"
#include "straightest/paths/base_plane.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

TEST(CuttingPlane, DestinationAlmostAlongTheBaseNormalHasNoPlane) {
  // Below a sine of 1e-8 the plane's normal is dominated by rounding (the fuzzer saw D 8e-7 off it).
  BasePlane base;
  base.origin = {0, 0, 0};
  base.normal = {0, 0, 1};
  EXPECT_FALSE(cuttingPlane(base, {1e-9, 0, 1}).has_value());
  const auto plane = cuttingPlane(base, {1e-7, 0, 1});
  ASSERT_TRUE(plane.has_value());
  EXPECT_LE(std::abs(dot(plane->normal, Vec3{1e-7, 0, 1})), 1e-15);
}

/// The normalized mean of the virtual faces' unit normals, computed here independently of basePlane.
Vec3 meanVirtualNormal(const TriMesh& mesh, const Vec3& s) {
  const auto& loop = mesh.boundaryLoops()[0];
  Vec3 sum;
  for (size_t i = 0; i < loop.size(); ++i)
    sum += normalized(cross(mesh.position(loop[i]) - s, mesh.position(loop[(i + 1) % loop.size()]) - s));
  return normalized(sum);
}

TEST(BasePlane, AlmostClosedCapKeepsThePapersMeanOfTheVirtualFaceNormals) {
  // A spherical cap of polar angle π − 0.05: a sphere with a small hole at the bottom. Seen from the
  // pole, the virtual faces to the tiny rim are slivers whose unit normals point almost every way around:
  // their mean is short (~0.016) but has a direction, so it is the base normal (no fallback).
  const TriMesh mesh = makeSphericalCap(1.0, testing::kPi - 0.05, 24);
  const BasePlane base = basePlane(mesh, SurfacePoint::vertex(0));
  EXPECT_FALSE(base.fallback) << base.note;
  const Vec3 mean = meanVirtualNormal(mesh, mesh.position(0));
  EXPECT_NEAR(std::abs(dot(base.normal, mean)), 1.0, 1e-12);
  EXPECT_NEAR(base.normal.z, 1.0, 1e-9);  // by symmetry, the axis
}

TEST(BasePlane, SphereSlitAlongAMeridianFallsBackToTheAreaWeightedNormalAndSaysSo) {
  // A latitude-longitude sphere cut open along the meridian y = 0, x > 0: a disk whose boundary runs down one
  // side of the slit and up the other. From the source on the opposite meridian (also in y = 0), every
  // virtual face lies in the plane y = 0 and the two sides' unit normals, ±y, cancel exactly.
  const int rings = 8, columns = 12;
  std::vector<Vec3> p;
  for (int j = 1; j < rings; ++j)
    for (int c = 0; c <= columns; ++c) {
      const double phi = testing::kPi * j / rings, lambda = 2 * testing::kPi * c / columns;
      const bool inSlitPlane = c == 0 || c == columns || 2 * c == columns;
      p.push_back(
          {std::sin(phi) * std::cos(lambda), inSlitPlane ? 0.0 : std::sin(phi) * std::sin(lambda), std::cos(phi)});
    }
  const int north = static_cast<int>(p.size()), south = north + 1;
  p.push_back({0, 0, 1});
  p.push_back({0, 0, -1});
  auto at = [&](int j, int c) { return (j - 1) * (columns + 1) + c; };
  std::vector<Triangle> t;
  for (int c = 0; c < columns; ++c) {
    t.push_back({north, at(1, c), at(1, c + 1)});
    t.push_back({south, at(rings - 1, c + 1), at(rings - 1, c)});
    for (int j = 1; j + 1 < rings; ++j) {
      t.push_back({at(j, c), at(j + 1, c), at(j + 1, c + 1)});
      t.push_back({at(j, c), at(j + 1, c + 1), at(j, c + 1)});
    }
  }
  const TriMesh mesh = testing::buildOrFail(p, t);
  ASSERT_EQ(mesh.boundaryLoops().size(), 1u);
  const SurfacePoint source = SurfacePoint::vertex(at(rings / 2, columns / 2));  // (−1, 0, 0)
  const BasePlane base = basePlane(mesh, source);
  EXPECT_TRUE(base.fallback);
  EXPECT_NE(base.note.find("cancel"), std::string::npos) << base.note;
  const Vec3 local = areaWeightedNormal(mesh, source);
  EXPECT_EQ(base.normal.x, local.x);
  EXPECT_EQ(base.normal.y, local.y);
  EXPECT_EQ(base.normal.z, local.z);
  EXPECT_GT(std::abs(base.normal.x), 0.99);  // the sphere's normal there
}

TEST(BasePlane, ClosedMeshUsesTheAreaWeightedNormalAndReportsTheFallback) {
  const TriMesh mesh = testing::icosphere(1);
  const BasePlane base = basePlane(mesh, SurfacePoint::vertex(3));
  EXPECT_TRUE(base.fallback);
  EXPECT_NE(base.note.find("closed"), std::string::npos) << base.note;
  EXPECT_NE(base.note.find("area-weighted normal"), std::string::npos) << base.note;  // says what was used
  EXPECT_NEAR(dot(base.normal, mesh.position(3)), 1.0, 1e-2);
}

TEST(BasePlane, NormalFacesTheSurfaceSideEvenNextToTheHoleOfANearlyClosedMesh) {
  const TriMesh sphere = testing::icosphere(2);
  std::vector<Triangle> kept;
  for (const Triangle& t : sphere.triangles())
    if (t[0] != 0 && t[1] != 0 && t[2] != 0) kept.push_back(t);
  const TriMesh mesh = testing::buildOrFail(sphere.positions(), kept);  // vertex 0 is now unreferenced
  for (int32_t v = 1; v < mesh.numVertices(); ++v) {
    if (mesh.isBoundaryVertex(v)) continue;
    const BasePlane base = basePlane(mesh, SurfacePoint::vertex(v));
    EXPECT_GT(dot(base.normal, mesh.position(v)), 0) << "vertex " << v << ": base plane faces into the sphere";
  }
}

}  // namespace
}  // namespace straightest
