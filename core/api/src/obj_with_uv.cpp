// obj_with_uv.cpp — the OBJ a map is written as (obj_with_uv.hpp).
#include "straightest/api/obj_with_uv.hpp"

#include <cmath>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

Expected<std::string> objWithUv(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  const size_t perVertex = static_cast<size_t>(mesh.numVertices());
  const size_t perCorner = 3 * static_cast<size_t>(mesh.numFaces());
  if (uv.size() != perVertex && uv.size() != perCorner)
    return Error{ErrorCode::InvalidArgument, "uv has " + std::to_string(2 * uv.size()) +
                                                 " numbers, expected 2 per vertex (" + std::to_string(2 * perVertex) +
                                                 ") or 2 per face corner (" + std::to_string(2 * perCorner) + ")"};
  if (uv.size() != perVertex) return writeObjWithCornerUv(mesh, uv);
  // A vertex's vt is always written, so it must be a number ("vt nan nan" is no OBJ); a corner without a map
  // (NaN in cornerUv: a face of another component) only leaves its face without vt.
  for (size_t v = 0; v < uv.size(); ++v)
    for (int k = 0; k < 2; ++k) {
      const double x = k == 0 ? uv[v].x : uv[v].y;
      if (!std::isfinite(x))
        return Error{ErrorCode::NonFinite, "uv[" + std::to_string(2 * v + k) + "] is " + std::to_string(x) +
                                               ", not a finite number (vertex " + std::to_string(v) + ")"};
    }
  return writeObj(mesh, &uv);
}

std::string objOfParameterization(const TriMesh& mesh, const Parameterization& p) {
  return p.cut == CutMethod::Disk ? writeObj(mesh, &p.uv) : writeObjWithCornerUv(mesh, p.cornerUv);
}

}  // namespace straightest
