// The built-in samples (and the closed generators) are valid meshes with the geometry their names promise.
#include <cmath>

#include <gtest/gtest.h>

#include "straightest/mesh/samples.hpp"

namespace straightest {
namespace {

TEST(Samples, EverySampleIsAConsistentlyOrientedConnectedMeshWithoutDegenerateFaces) {
  for (const std::string& name : sampleNames()) {
    auto mesh = makeSample(name);
    ASSERT_TRUE(mesh.ok()) << name << ": " << mesh.error().message;
    const MeshSummary& s = mesh.value().summary();
    EXPECT_EQ(s.components, 1) << name;
    EXPECT_EQ(s.degenerateFaces, 0) << name;
    EXPECT_EQ(s.reorientedFaces, 0) << name;
    EXPECT_EQ(s.unreferencedVertices, 0) << name;
  }
}

TEST(Samples, TheReliefsAreUpwardFacingDisksTheOthersHaveTheTopologyTheirNamesSay) {
  for (const std::string name : {"mountain", "cap", "saddle", "face", "holes"}) {
    const TriMesh mesh = makeSample(name).value();
    const MeshSummary& s = mesh.summary();
    // χ = 2 − 2g − k with genus 0: a disk has one loop, the holes sample four.
    const size_t loops = name == "holes" ? 4 : 1;
    EXPECT_EQ(s.boundaryLoopSizes.size(), loops) << name;
    EXPECT_EQ(s.eulerCharacteristic, 2 - static_cast<int64_t>(loops)) << name;
    for (int f = 0; f < mesh.numFaces(); ++f)
      ASSERT_GT(mesh.faceNormal(f).z, 0) << name << ": face " << f << " faces down";
  }
  const TriMesh sphere = makeSample("sphere").value(), torus = makeSample("torus").value();
  EXPECT_TRUE(sphere.boundaryLoops().empty());
  EXPECT_EQ(sphere.summary().eulerCharacteristic, 2);
  EXPECT_TRUE(torus.boundaryLoops().empty());
  EXPECT_EQ(torus.summary().eulerCharacteristic, 0);  // genus 1
  int samplesSeen = 0;
  for (const std::string& name : sampleNames()) samplesSeen += makeSample(name).ok();
  EXPECT_EQ(samplesSeen, 7) << "every name is checked above";
}

TEST(Samples, MountainIsThePapers2500VertexHeightField) {
  const TriMesh mesh = makeSample("mountain").value();
  EXPECT_EQ(mesh.numVertices(), 2500);
  EXPECT_EQ(mesh.numFaces(), 2 * 49 * 49);
  EXPECT_EQ(mesh.boundaryLoops()[0].size(), 4u * 49);
}

TEST(Samples, CapVerticesLieOnTheUnitSphereWithinItsPolarAngle) {
  const double thetaMax = 3.14159265358979323846 / 3;
  const TriMesh mesh = makeSphericalCap(1.0, thetaMax, 8);
  EXPECT_EQ(mesh.numVertices(), 1 + 3 * 8 * 9);
  for (const Vec3& p : mesh.positions()) {
    EXPECT_NEAR(norm(p), 1.0, 1e-12);
    EXPECT_GE(p.z, std::cos(thetaMax) - 1e-12);
  }
  for (int v : mesh.boundaryLoops()[0]) EXPECT_NEAR(mesh.position(v).z, std::cos(thetaMax), 1e-12);
}

TEST(Samples, UnknownNameListsTheAvailableOnes) {
  auto mesh = makeSample("teapot");
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.error().code, ErrorCode::InvalidArgument);
  EXPECT_NE(mesh.error().message.find("mountain"), std::string::npos);
}

TEST(Samples, IcosphereIsAClosedSphereOfTheGivenRadius) {
  const TriMesh mesh = makeIcosphere(2.5, 3);
  EXPECT_EQ(mesh.numVertices(), 642);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 2);
  EXPECT_TRUE(mesh.boundaryLoops().empty());
  EXPECT_EQ(mesh.summary().reorientedFaces, 0);
  for (const Vec3& p : mesh.positions()) EXPECT_NEAR(norm(p), 2.5, 1e-12);
  // Outward orientation: every face normal points away from the centre.
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    EXPECT_GT(dot(mesh.faceNormal(f), mesh.position(mesh.triangle(f)[0])), 0);
}

TEST(Samples, TorusIsClosedOfGenusOneWithItsTubeOnTheGivenRadii) {
  const double R = 3, r = 1;
  const TriMesh mesh = makeTorus(R, r, 24, 12);
  EXPECT_EQ(mesh.numVertices(), 24 * 12);
  EXPECT_EQ(mesh.summary().eulerCharacteristic, 0);
  EXPECT_TRUE(mesh.boundaryLoops().empty());
  EXPECT_EQ(mesh.summary().reorientedFaces, 0);
  for (const Vec3& p : mesh.positions()) {
    const double rho = std::hypot(p.x, p.y);  // distance from the z axis
    EXPECT_NEAR(std::hypot(rho - R, p.z), r, 1e-12);
  }
  // Outward: away from the tube's centre circle.
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    Vec3 c{0, 0, 0};
    for (int32_t v : mesh.triangle(f)) c = c + mesh.position(v) * (1.0 / 3);
    const double rho = std::hypot(c.x, c.y);
    const Vec3 centre{c.x * R / rho, c.y * R / rho, 0};
    EXPECT_GT(dot(mesh.faceNormal(f), c - centre), 0);
  }
}

}  // namespace
}  // namespace straightest
