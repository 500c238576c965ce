// vec3.hpp — small 2D and 3D vectors of doubles with the handful of operations the geometry needs.
// A plain value type (no alignment requirements) so positions can live in flat std::vector<Vec3>
// and be copied to JS as one contiguous block of doubles.
#pragma once
#include <array>
#include <cmath>

namespace straightest {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2 * kPi;

/// A point or vector in the parameter plane (u, v). Indexable ([0] is u) so loops over both
/// coordinates stay loops.
struct Vec2 {
  double x = 0, y = 0;

  constexpr Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

  constexpr Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
  Vec2& operator+=(const Vec2& o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  Vec2& operator-=(const Vec2& o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
  constexpr bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }
  constexpr bool operator!=(const Vec2& o) const { return !(*this == o); }
  double& operator[](int i) { return i == 0 ? x : y; }
  constexpr double operator[](int i) const { return i == 0 ? x : y; }
};

inline constexpr Vec2 operator*(double s, const Vec2& v) { return v * s; }
inline constexpr double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
/// The z component of the 3D cross product: twice the signed area of the triangle (0, a, b).
inline constexpr double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline double norm(const Vec2& a) { return std::hypot(a.x, a.y); }
inline constexpr double squaredNorm(const Vec2& a) { return dot(a, a); }
inline bool isFinite(const Vec2& a) { return std::isfinite(a.x) && std::isfinite(a.y); }

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  Vec3& operator*=(double s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

inline constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
inline constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
/// The largest |component| of a: the scale by which a can be divided without overflow or underflow.
inline double largestComponent(const Vec3& a) {
  return std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z)));
}
/// |a| also when squaring the components would underflow (below ~1e-154) or overflow (above ~1e154):
/// there norm() loses digits or returns inf, and a vector divided by it is no longer unit length.
/// In the ordinary range it returns exactly what norm() returns.
inline double robustNorm(const Vec3& a) {
  const double s = dot(a, a);
  if (s > 1e-290 && s < 1e290) return std::sqrt(s);
  const double m = largestComponent(a);
  if (!(m > 0) || !std::isfinite(m)) return m;  // zero, inf or NaN: nothing to rescale
  return m * norm(a / m);
}
inline constexpr double squaredNorm(const Vec3& a) { return dot(a, a); }
inline bool isFinite(const Vec3& a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
/// Unit vector along a; the zero vector stays zero (callers decide what a zero direction means).
inline Vec3 normalized(const Vec3& a) {
  const double n = norm(a);
  return n > 0 ? a / n : Vec3{};
}

}  // namespace straightest
