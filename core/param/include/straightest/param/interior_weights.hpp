// interior_weights.hpp — linear convex-combination weights for the interior of a disk map.
// Each interior vertex i gets weights λ_ij over its one-ring neighbours j with Σ_j λ_ij = 1; the
// parameterization solves u_i = Σ_j λ_ij u_j (Tutte/Floater). Kinds:
//  - uniform: λ_ij = 1/deg(i) (Tutte).
//  - shape-preserving (Floater 1997): the one ring is flattened by the geodesic polar map (angles at i
//    scaled to sum 2π, edge lengths kept); for every neighbour k, the ray from q_k through the centre
//    hits the opposite segment [q_l, q_l+1]; the barycentric coordinates of the centre in
//    (q_k, q_l, q_l+1) are averaged over k.
//  - mean-value (Floater 2003): w_ij = (tan(α_ij⁻/2) + tan(α_ij⁺/2)) / |p_j − p_i|, normalized.
//  - cotan (harmonic): w_ij = cot β_ij + cot γ_ij, normalized; can be negative (not a convex
//    combination: obtuse meshes may flip).
// Degenerate one rings (zero-length edges, zero angle sums) fall back to uniform for that vertex; the
// count is reported.
#pragma once
#include <vector>

#include "straightest/base/names.hpp"
#include "straightest/mesh/trimesh.hpp"
#include "straightest/solver/csr_matrix.hpp"

namespace straightest {

enum class WeightKind { ShapePreserving, MeanValue, Cotan, Uniform };
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<WeightKind> kWeightKindNames[] = {{WeightKind::ShapePreserving, "shape-preserving"},
                                                            {WeightKind::MeanValue, "mean-value"},
                                                            {WeightKind::Cotan, "cotan"},
                                                            {WeightKind::Uniform, "uniform"}};
const char* weightKindName(WeightKind k);
Expected<WeightKind> parseWeightKind(const std::string& name);

struct InteriorWeights {
  std::vector<int32_t> rows;  // the interior vertices: row r of `weights` belongs to vertex rows[r]
  CsrMatrix weights;          // rows.size() × vertices: row r holds λ_rj at column j, one entry per neighbour
  int64_t uniformFallbacks = 0;
};

/// Weights for every interior (non-boundary, referenced) vertex of a mesh with boundary.
InteriorWeights interiorWeights(const TriMesh& mesh, WeightKind kind);

/// The linear system the weights define: u_i − Σ_j λ_ij u_j = 0 over the interior rows (row r = vertex
/// W.rows[r]), with the vertices outside W.rows fixed.
struct InteriorSystem {
  CsrMatrix A;              // I − W restricted to the interior (a row is its diagonal, then its interior neighbours)
  std::vector<double> rhs;  // the fixed neighbours' contribution, u and v interleaved (2 values per row)
};

/// Assembles the system with the vertices outside W.rows fixed at `fixed` (one entry per mesh vertex;
/// only the boundary's are read).
InteriorSystem assembleInteriorSystem(const InteriorWeights& W, const std::vector<Vec2>& fixed);

}  // namespace straightest
