// flat_faces.cpp — the records of flat_faces.hpp.
#include "straightest/mesh/flat_faces.hpp"

#include "straightest/base/parallel_for.hpp"

namespace straightest {

std::vector<FlatFace> flatFaces(const TriMesh& mesh) {
  std::vector<FlatFace> faces(static_cast<size_t>(mesh.numFaces()));
  detail::parallelFor(faces.size(), 1 << 15, [&](size_t, size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f) {
      FlatFace& r = faces[f];
      makeFlatFace(mesh, static_cast<int32_t>(f), r);
      for (int k = 0; k < 3; ++k) {
        const int32_t t = r.twins[k];
        if (t < 0) {
          r.beyond[2 * k] = r.beyond[2 * k + 1] = static_cast<int32_t>(f);
          continue;
        }
        const std::array<int32_t, 3>& across = mesh.adjacency(TriMesh::face(t)).twins;
        const int m = t % 3;
        for (int i = 1; i <= 2; ++i) {
          const int32_t u = across[(m + i) % 3];
          r.beyond[2 * k + i - 1] = u < 0 ? static_cast<int32_t>(f) : TriMesh::face(u);
        }
      }
    }
  });
  return faces;
}

}  // namespace straightest
