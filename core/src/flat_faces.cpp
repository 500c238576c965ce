// flat_faces.cpp — the records of flat_faces.hpp.
#include "flat_faces.hpp"

#include "parallel_for.hpp"

namespace straightest {

std::vector<FlatFace> flatFaces(const TriMesh& mesh) {
  std::vector<FlatFace> faces(static_cast<size_t>(mesh.numFaces()));
  detail::parallelFor(faces.size(), 1 << 15, [&](size_t, size_t begin, size_t end) {
    for (size_t f = begin; f < end; ++f) makeFlatFace(mesh, static_cast<int32_t>(f), faces[f]);
  });
  return faces;
}

}  // namespace straightest
