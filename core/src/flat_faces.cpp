// flat_faces.cpp — the records of flat_faces.hpp.
#include "flat_faces.hpp"

#include <cmath>

#include "parallel_for.hpp"

namespace straightest {

FlatFace flatFace(const TriMesh& mesh, int32_t f) {
  const FaceAdjacency& face = mesh.adjacency(f);
  FlatFace r;
  r.twins = face.twins;
  if (mesh.isDegenerateFace(f)) return r;
  const Vec3& a = mesh.position(face.corners[0]);
  const Vec3 e = mesh.position(face.corners[1]) - a, w = mesh.position(face.corners[2]) - a;
  const double length = std::sqrt(dot(e, e));
  r.x = {0, length, dot(w, e) / length};
  r.y = {0, 0, norm(cross(e, w)) / length};
  return r;
}

std::vector<FlatFace> flatFaces(const TriMesh& mesh) {
  std::vector<FlatFace> faces(static_cast<size_t>(mesh.numFaces()));
  detail::parallelFor(faces.size(), 1 << 15, [&](size_t, size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f) faces[f] = flatFace(mesh, static_cast<int32_t>(f));
  });
  return faces;
}

}  // namespace straightest
