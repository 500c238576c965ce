// symmetric_dirichlet.hpp — the per-triangle pieces of an isometric distortion energy: each face's
// gradient operator in its own 3D frame (so a map's Jacobian is a 2 × 2 matrix), the symmetric
// Dirichlet energy ‖J‖²_F + ‖J⁻¹‖²_F (4 for an isometry, +∞ for a flipped or zero-area image) with its
// derivative, and the largest step along a direction before some triangle's 2D area reaches zero.
// Private to the free-boundary refinement and the untangler.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "straightest/mesh/trimesh.hpp"

namespace straightest {

/// A 2 × 2 matrix, row-major: [[a, b], [c, d]] (rows are ∇u and ∇v in a face's frame).
struct Mat2 {
  double a = 0, b = 0, c = 0, d = 0;
  double det() const { return a * d - b * c; }
  double squaredNorm() const { return a * a + b * b + c * c + d * d; }
};

/// The gradient of the piecewise-linear hat functions of one face, in an orthonormal frame of its
/// plane: ∇f = Σ_k f_k (gx[k], gy[k]). Faces with (almost) no 3D area have area 0 and a zero operator.
struct FaceGradient {
  std::array<double, 3> gx{}, gy{};
  double area = 0;
};

/// One operator per face. A face the mesh reports degenerate (isDegenerateFace: no measurable 3D area)
/// gets, when `regularizeDegenerate`, the operator of an equilateral triangle of the mean face area
/// (so an untangler still has a shape to aim for), otherwise area 0 (it carries no energy).
std::vector<FaceGradient> faceGradients(const TriMesh& mesh, bool regularizeDegenerate);

/// The Jacobian of the map uv on face f: rows ∇u, ∇v.
inline Mat2 jacobian(const FaceGradient& g, const Triangle& t, const std::vector<Vec2>& uv) {
  Mat2 j;
  for (int k = 0; k < 3; ++k) {
    const Vec2& q = uv[t[k]];
    j.a += g.gx[k] * q.x;
    j.b += g.gy[k] * q.x;
    j.c += g.gx[k] * q.y;
    j.d += g.gy[k] * q.y;
  }
  return j;
}

/// Twice the signed area of face t in uv.
inline double twiceSignedArea(const Triangle& t, const std::vector<Vec2>& uv) {
  return cross(uv[t[1]] - uv[t[0]], uv[t[2]] - uv[t[0]]);
}

/// ‖J‖²_F + ‖J⁻¹‖²_F = ‖J‖²_F (1 + 1/det²); +∞ when det ≤ 0.
double symmetricDirichlet(const Mat2& j);

/// Its derivative with respect to J's entries (J finite, det > 0).
Mat2 symmetricDirichletGradient(const Mat2& j);

/// SLIM's local step for one face (Rabinovich et al. 2017): the rotation closest to J and the weight
/// M = V diag(w(σ₁), w(σ₂)) Vᵀ of the proxy ‖(J − R) M^½‖²_F, in the face's frame (J = U Σ Vᵀ), with
/// w(σ) = (σ + 1)(σ² + 1)/σ³, SLIM's f'(σ) / (2(σ − 1)) for f = σ² + σ⁻² with the division done by
/// hand. The proxy's gradient at J, 2 (J − R) M, is the energy's (symmetricDirichletGradient). J must
/// have det > 0.
void slimLocalStep(const Mat2& j, Mat2& weight, Mat2& rotation);

/// The area-weighted sums of ‖J‖²_F and ‖J⁻¹‖²_F over the faces (+∞ second term when a face of
/// positive area has det ≤ 0). The energy per unit area is (first + second) / Σ area; scaling the
/// map by s multiplies the first by s² and the second by 1/s².
struct DirichletSums {
  double direct = 0, inverse = 0, area = 0;
  double perUnitArea() const { return (direct + inverse) / area; }
};
DirichletSums dirichletSums(const TriMesh& mesh, const std::vector<FaceGradient>& gradients,
                            const std::vector<Vec2>& uv);

/// The largest t in (0, ∞] for which uv + s·direction keeps every face's signed area positive for all
/// s in [0, t) (per face, the smallest positive root of the quadratic area(s)). Faces already at zero
/// or negative area are ignored (the caller keeps them out of the start).
double largestFlipFreeStep(const TriMesh& mesh, const std::vector<Vec2>& uv, const std::vector<Vec2>& direction);

}  // namespace straightest
