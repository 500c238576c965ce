// base_plane.cpp — the base plane at the source, a cutting plane toward a destination, vertex normals.
#include "straightest/paths/base_plane.hpp"

#include <cmath>
#include <vector>

namespace straightest {

Vec3 areaWeightedNormal(const TriMesh& mesh, const SurfacePoint& p) {
  std::vector<int32_t> faces;
  incidentFaces(mesh, p, faces);
  Vec3 sum;
  for (int32_t f : faces) sum += mesh.faceNormal(f) * mesh.faceArea(f);
  return normalized(sum);
}

std::vector<Vec3> vertexNormals(const TriMesh& mesh) {
  std::vector<Vec3> sums(mesh.numVertices());
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    const Vec3 weighted = mesh.faceNormal(f) * mesh.faceArea(f);
    for (int32_t v : mesh.triangle(f)) sums[v] += weighted;
  }
  for (Vec3& n : sums) n = normalized(n);
  return sums;
}

BasePlane basePlane(const TriMesh& mesh, const SurfacePoint& source) {
  BasePlane base;
  base.origin = position(mesh, source);
  if (mesh.boundaryLoops().empty()) {
    base.normal = areaWeightedNormal(mesh, source);
    base.fallback = true;
    base.note = "closed mesh (no boundary loop for the virtual faces): area-weighted normal at the source used";
    return base;
  }
  const auto& loop = mesh.boundaryLoops()[0];
  Vec3 sum;
  double lengths = 0;  // the sum of the unit normals' lengths: the number of non-degenerate virtual faces
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = mesh.position(loop[i]) - base.origin;
    const Vec3 b = mesh.position(loop[(i + 1) % loop.size()]) - base.origin;
    const Vec3 unit = normalized(cross(a, b));  // unit normal of the virtual face (S, b_i, b_i+1); zero if degenerate
    sum += unit;
    lengths += norm(unit);
  }
  const Vec3 mean = sum / static_cast<double>(loop.size());
  if (!(norm(sum) > kBaseNormalCancel * lengths)) {
    base.normal = areaWeightedNormal(mesh, source);
    base.fallback = true;
    base.note = "the virtual-face normals cancel (|mean| = " + std::to_string(norm(mean)) +
                "): area-weighted normal at the source used";
    return base;
  }
  // Orient like the surface at S. (The mesh's total area-weighted normal, the obvious alternative, points
  // away from the hole of a nearly closed surface and would flip the base plane of sources near it.)
  const Vec3 local = areaWeightedNormal(mesh, source);
  base.normal = normalized(dot(mean, local) < 0 ? -mean : mean);
  return base;
}

std::optional<CuttingPlane> cuttingPlane(const BasePlane& base, const Vec3& destination) {
  const Vec3 d = destination - base.origin;
  const Vec3 m = cross(base.normal, d);
  const double len = norm(d);
  if (!(len > 0) || !(norm(m) > kCuttingPlaneMinSine * len)) return std::nullopt;
  return CuttingPlane{base.origin, normalized(m)};
}

std::optional<Vec3> inPlaneDirection(const BasePlane& base, const Vec3& destination) {
  if (!cuttingPlane(base, destination)) return std::nullopt;
  const Vec3 d = destination - base.origin;
  return normalized(d - base.normal * dot(base.normal, d));
}

}  // namespace straightest
