// Vec2 and Vec3: the small vector algebra every module builds on (2D for the parameter plane).
#include <cmath>

#include <gtest/gtest.h>

#include "straightest/base/vec3.hpp"

namespace straightest {
namespace {

TEST(Vec2, ArithmeticIsComponentWise) {
  const Vec2 a{1.5, -2}, b{0.25, 4};
  EXPECT_EQ(a + b, Vec2(1.75, 2));
  EXPECT_EQ(a - b, Vec2(1.25, -6));
  EXPECT_EQ(-a, Vec2(-1.5, 2));
  EXPECT_EQ(a * 2, Vec2(3, -4));
  EXPECT_EQ(2 * a, a * 2);
  EXPECT_EQ(a / 2, Vec2(0.75, -1));
  Vec2 c = a;
  c += b;
  c -= a;
  EXPECT_EQ(c, b);
  c *= -1;
  EXPECT_EQ(c, -b);
  EXPECT_NE(a, b);
}

TEST(Vec2, IndexingReadsAndWritesUThenV) {
  Vec2 a{3, 7};
  EXPECT_EQ(a[0], 3);
  EXPECT_EQ(a[1], 7);
  a[1] = -1;
  EXPECT_EQ(a.y, -1);
  EXPECT_EQ(a.x, 3);
}

TEST(Vec2, CrossIsTwiceTheSignedAreaPositiveCounterClockwise) {
  const Vec2 o{1, 1}, p{4, 1}, q{1, 3};  // right triangle with legs 3 and 2, counter-clockwise
  EXPECT_EQ(cross(p - o, q - o), 6);
  EXPECT_EQ(cross(q - o, p - o), -6);
  EXPECT_EQ(cross(p - o, (p - o) * 2.5), 0);  // parallel vectors span no area
  EXPECT_EQ(dot(p - o, q - o), 0);            // the legs are perpendicular
  EXPECT_EQ(dot(p - o, p - o), 9);
}

TEST(Vec2, NormIsTheEuclideanLengthWithoutOverflow) {
  EXPECT_EQ(norm(Vec2{3, 4}), 5);
  EXPECT_EQ(squaredNorm(Vec2{3, 4}), 25);
  EXPECT_DOUBLE_EQ(norm(Vec2{3e200, 4e200}), 5e200);  // squares would overflow; the length does not
  EXPECT_TRUE(isFinite(Vec2{1, 2}));
  EXPECT_FALSE(isFinite(Vec2{1, NAN}));
  EXPECT_FALSE(isFinite(Vec2{INFINITY, 0}));
}

TEST(Vec3, CrossIsPerpendicularAndRightHanded) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  const Vec3 z = cross(x, y);
  EXPECT_EQ(z.x, 0);
  EXPECT_EQ(z.y, 0);
  EXPECT_EQ(z.z, 1);
  const Vec3 a{1, 2, 3}, b{-4, 0.5, 2};
  EXPECT_NEAR(dot(cross(a, b), a), 0, 1e-14);
  EXPECT_NEAR(dot(cross(a, b), b), 0, 1e-14);
  EXPECT_EQ(norm(normalized(Vec3{0, 3, 4})), 1);
  const Vec3 zero = normalized(Vec3{});  // a zero direction stays zero instead of becoming NaN
  EXPECT_EQ(zero.x, 0);
  EXPECT_EQ(zero.y, 0);
  EXPECT_EQ(zero.z, 0);
}

TEST(Constants, TwoPiIsAFullTurn) {
  EXPECT_EQ(kTwoPi, 2 * kPi);
  EXPECT_NEAR(std::cos(kTwoPi), 1, 1e-15);
  EXPECT_NEAR(std::sin(kPi), 0, 1e-15);
  EXPECT_NEAR(std::cos(kPi), -1, 1e-15);
}

}  // namespace
}  // namespace straightest
