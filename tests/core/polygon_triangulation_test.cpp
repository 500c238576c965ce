// Polygon triangulation: n − 2 triangles that cover the polygon exactly, inside its outline, with its
// winding, in any plane; degenerate and very large polygons fall back to a fan.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/mesh/polygon_triangulation.hpp"
#include "test_meshes.hpp"

namespace straightest {
namespace {

/// Sum of the triangles' area vectors (each (b − a) × (c − a) / 2).
Vec3 areaVector(const std::vector<Vec3>& p, const std::vector<Triangle>& triangles) {
  Vec3 sum;
  for (const Triangle& t : triangles) sum += cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]) * 0.5;
  return sum;
}

std::vector<int32_t> firstN(size_t n) {
  std::vector<int32_t> polygon(n);
  for (size_t i = 0; i < n; ++i) polygon[i] = static_cast<int32_t>(i);
  return polygon;
}

/// The L-shaped hexagon (area 3) with corners mapped into the plane through `origin` spanned by u, w.
std::vector<Vec3> lHexagon(const Vec3& origin, const Vec3& u, const Vec3& w) {
  std::vector<Vec3> p;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
    p.push_back(origin + u * x + w * y);
  return p;
}

TEST(PolygonTriangulation, NonConvexPolygonIsCoveredExactlyByTrianglesInsideItsOutline) {
  // Starting at corner (2, 0), a fan would fold over the reflex corner (1, 1): its triangle
  // (2, 0) (1, 1) (1, 2) is clockwise and reaches outside the L.
  const std::vector<Vec3> p = lHexagon({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  std::vector<Triangle> triangles;
  triangulatePolygon(p, {1, 2, 3, 4, 5, 0}, triangles);
  ASSERT_EQ(triangles.size(), 4u);
  double unsignedArea = 0;
  for (const Triangle& t : triangles) {
    const Vec3 n = cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    EXPECT_GT(n.z, 0) << "a triangle is flipped or flat";
    unsignedArea += norm(n) / 2;
    const Vec3 centroid = (p[t[0]] + p[t[1]] + p[t[2]]) / 3;
    EXPECT_TRUE(centroid.x < 1 || centroid.y < 1) << "a triangle lies in the L's missing square";
  }
  EXPECT_NEAR(unsignedArea, 3.0, 1e-12);  // no overlap: the unsigned areas add up to the polygon's
}

TEST(PolygonTriangulation, KeepsThePolygonsWindingInATiltedPlane) {
  const Vec3 u = normalized(Vec3{1, 1, 1}), w = normalized(cross(Vec3{0, 0, 1}, u));
  std::vector<Vec3> p = lHexagon({5, -3, 2}, u, w);
  const Vec3 normal = cross(u, w);
  for (bool reversed : {false, true}) {
    std::vector<int32_t> polygon{1, 2, 3, 4, 5, 0};
    if (reversed) std::reverse(polygon.begin(), polygon.end());
    std::vector<Triangle> triangles;
    triangulatePolygon(p, polygon, triangles);
    ASSERT_EQ(triangles.size(), 4u);
    const double sign = reversed ? -1 : 1;
    for (const Triangle& t : triangles) EXPECT_GT(sign * dot(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]), normal), 0);
    EXPECT_NEAR(dot(areaVector(p, triangles), normal), sign * 3.0, 1e-12);
  }
}

TEST(PolygonTriangulation, ConvexPolygonGivesNMinusTwoTrianglesOfItsArea) {
  const size_t n = 12;
  std::vector<Vec3> p;
  for (size_t i = 0; i < n; ++i) {
    const double a = 2 * testing::kPi * static_cast<double>(i) / n;
    p.push_back({std::cos(a), std::sin(a), 0});
  }
  std::vector<Triangle> triangles;
  triangulatePolygon(p, firstN(n), triangles);
  EXPECT_EQ(triangles.size(), n - 2);
  EXPECT_NEAR(areaVector(p, triangles).z, 0.5 * n * std::sin(2 * testing::kPi / n), 1e-12);
}

TEST(PolygonTriangulation, PolygonsTooDegenerateOrTooLargeToClipAreFanned) {
  // All corners on a line: no plane, so a fan from the first corner (n − 2 flat triangles).
  const std::vector<Vec3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  std::vector<Triangle> triangles;
  triangulatePolygon(line, firstN(5), triangles);
  ASSERT_EQ(triangles.size(), 3u);
  for (const Triangle& t : triangles) EXPECT_EQ(t[0], 0);
  // 300 corners (over the ear-clipping bound of 256): a fan, still exactly covering a convex polygon.
  const size_t n = 300;
  std::vector<Vec3> circle;
  for (size_t i = 0; i < n; ++i) {
    const double a = 2 * testing::kPi * static_cast<double>(i) / n;
    circle.push_back({std::cos(a), std::sin(a), 0});
  }
  triangles.clear();
  triangulatePolygon(circle, firstN(n), triangles);
  ASSERT_EQ(triangles.size(), n - 2);
  for (const Triangle& t : triangles) EXPECT_EQ(t[0], 0);
  EXPECT_NEAR(areaVector(circle, triangles).z, 0.5 * n * std::sin(2 * testing::kPi / n), 1e-12);
}

TEST(PolygonTriangulation, FewerThanThreeCornersGiveNoTriangle) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}};
  std::vector<Triangle> triangles;
  triangulatePolygon(p, {0, 1}, triangles);
  triangulatePolygon(p, {}, triangles);
  EXPECT_TRUE(triangles.empty());
}

}  // namespace
}  // namespace straightest
