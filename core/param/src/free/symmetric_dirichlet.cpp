// symmetric_dirichlet.cpp — the symmetric Dirichlet energy per face, SLIM's local step, the flip-free step.
#include "symmetric_dirichlet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace straightest {
namespace {

/// The hat-function gradients of the plane triangle (0, 0), p1, p2 (counter-clockwise, twice area
/// 2a > 0): ∇φ_k = perp(p_{k+2} − p_{k+1}) / 2a, perp(x, y) = (−y, x).
FaceGradient planeGradient(const std::array<Vec2, 3>& p, double area) {
  FaceGradient g;
  g.area = area;
  for (int k = 0; k < 3; ++k) {
    const Vec2 e = p[(k + 2) % 3] - p[(k + 1) % 3];
    g.gx[k] = -e.y / (2 * area);
    g.gy[k] = e.x / (2 * area);
  }
  return g;
}

}  // namespace

std::vector<FaceGradient> faceGradients(const TriMesh& mesh, bool regularizeDegenerate) {
  const int32_t nf = mesh.numFaces();
  std::vector<FaceGradient> g(nf);
  double meanArea = 0;
  int32_t counted = 0;
  for (int32_t f = 0; f < nf; ++f)
    if (!mesh.isDegenerateFace(f)) {
      meanArea += mesh.faceArea(f);
      ++counted;
    }
  meanArea = counted > 0 ? meanArea / counted : 1;
  for (int32_t f = 0; f < nf; ++f) {
    if (mesh.isDegenerateFace(f)) {
      if (!regularizeDegenerate) continue;
      const double side = std::sqrt(4 * meanArea / std::sqrt(3.0));
      g[f] = planeGradient({Vec2{0, 0}, Vec2{side, 0}, Vec2{side / 2, side * std::sqrt(3.0) / 2}}, meanArea);
      continue;
    }
    const Triangle& t = mesh.triangle(f);
    const Vec3 e1 = mesh.position(t[1]) - mesh.position(t[0]), e2 = mesh.position(t[2]) - mesh.position(t[0]);
    const double l1 = norm(e1);
    const double x2 = dot(e2, e1) / l1;
    const double y2 = norm(cross(e1, e2)) / l1;
    g[f] = planeGradient({Vec2{0, 0}, Vec2{l1, 0}, Vec2{x2, y2}}, 0.5 * l1 * y2);
  }
  return g;
}

double symmetricDirichlet(const Mat2& j) {
  const double det = j.det();
  if (!(det > 0)) return std::numeric_limits<double>::infinity();
  return j.squaredNorm() * (1 + 1 / (det * det));
}

Mat2 symmetricDirichletGradient(const Mat2& j) {
  // E = s (1 + D⁻²), s = ‖J‖², D = det J: ∂E/∂J = 2 J (1 + D⁻²) − 2 s D⁻³ cof J, cof J = [[d, −c], [−b, a]].
  const double det = j.det(), s = j.squaredNorm();
  const double k = 2 * (1 + 1 / (det * det)), m = 2 * s / (det * det * det);
  return {k * j.a - m * j.d, k * j.b + m * j.c, k * j.c + m * j.b, k * j.d - m * j.a};
}

void slimLocalStep(const Mat2& j, Mat2& weight, Mat2& rotation) {
  // J = Rot(φ) diag(σ₁, σ₂) Rot(θ) with E, F, G, H below; Rot(φ + θ) is the closest rotation.
  const double e = 0.5 * (j.a + j.d), f = 0.5 * (j.a - j.d), g = 0.5 * (j.c + j.b), h = 0.5 * (j.c - j.b);
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  const double s1 = q + r, s2 = q - r;
  rotation = {e / q, -h / q, h / q, e / q};
  auto w = [](double s) { return (s + 1) * (s * s + 1) / (s * s * s); };
  const double w1 = w(s1), w2 = w(s2);
  // V diag(w₁, w₂) Vᵀ = (w₁ + w₂)/2 I + (w₁ − w₂)/2 V diag(1, −1) Vᵀ, a reflection by the angle 2θ.
  const double mean = 0.5 * (w1 + w2), half = 0.5 * (w1 - w2);
  double cos2 = 1, sin2 = 0;
  if (r > 0) {
    cos2 = (e * f + h * g) / (q * r);
    sin2 = (h * f - e * g) / (q * r);
  }
  weight = {mean + half * cos2, -half * sin2, -half * sin2, mean - half * cos2};
}

DirichletSums dirichletSums(const TriMesh& mesh, const std::vector<FaceGradient>& gradients,
                            const std::vector<Vec2>& uv) {
  DirichletSums sums;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const FaceGradient& g = gradients[f];
    if (!(g.area > 0)) continue;
    const Mat2 j = jacobian(g, mesh.triangle(f), uv);
    const double det = j.det(), s = j.squaredNorm();
    sums.direct += g.area * s;
    sums.inverse += det > 0 ? g.area * s / (det * det) : std::numeric_limits<double>::infinity();
    sums.area += g.area;
  }
  return sums;
}

double largestFlipFreeStep(const TriMesh& mesh, const std::vector<Vec2>& uv, const std::vector<Vec2>& direction) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : mesh.triangles()) {
    const Vec2 e1 = uv[t[1]] - uv[t[0]], e2 = uv[t[2]] - uv[t[0]];
    const Vec2 d1 = direction[t[1]] - direction[t[0]], d2 = direction[t[2]] - direction[t[0]];
    // area(s) ∝ c + b s + a s², c > 0: the first positive root is where the face would flip.
    const double c = cross(e1, e2);
    if (!(c > 0)) continue;
    const double b = cross(e1, d2) + cross(d1, e2), a = cross(d1, d2);
    double root = std::numeric_limits<double>::infinity();
    if (std::abs(a) <= 1e-14 * (std::abs(b) + c)) {
      if (b < 0) root = -c / b;
    } else {
      const double disc = b * b - 4 * a * c;
      if (disc >= 0) {
        // Stable roots q / a and c / q; keep the smallest positive one.
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        for (double r : {q / a, q != 0 ? c / q : std::numeric_limits<double>::infinity()})
          if (r > 0) root = std::min(root, r);
      }
    }
    best = std::min(best, root);
  }
  return best;
}

}  // namespace straightest
