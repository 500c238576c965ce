// The base plane at a source and the cutting plane toward a destination: the normal faces the surface's
// side, falls back (and says so) where the virtual faces cancel, and there is no plane toward a point
// along the normal.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/base_plane.hpp"
#include "straightest/samples.hpp"
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

TEST(BasePlane, AlmostClosedCapFallsBackToTheAreaWeightedNormalAndSaysSo) {
  // A spherical cap of polar angle π − 0.05: a sphere with a small hole at the bottom. Seen from the
  // pole, the virtual faces to the tiny rim are slivers whose unit normals point every way around:
  // their mean nearly cancels, so the base normal falls back to the area-weighted normal (reported).
  const TriMesh mesh = makeSphericalCap(1.0, testing::kPi - 0.05, 24);
  const BasePlane base = basePlane(mesh, SurfacePoint::vertex(0));
  EXPECT_TRUE(base.fallback);
  EXPECT_NE(base.note.find("cancel"), std::string::npos) << base.note;
  EXPECT_NEAR(base.normal.z, 1.0, 1e-9);  // the pole's own normal
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
