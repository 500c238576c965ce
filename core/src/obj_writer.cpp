// The OBJ writer (declared in mesh_io.hpp): a mesh, and optionally one texture coordinate per vertex,
// as OBJ text. Coordinates are written with 17 significant digits, so reading the file back gives
// exactly the same doubles; vertices keep the mesh's order, so `vt` k belongs to vertex k.
#include <cstdio>

#include "straightest/mesh_io.hpp"

namespace straightest {

std::string writeObj(const TriMesh& mesh, const std::vector<Vec2>* uv) {
  std::string out = "# written by straightest\n";
  char line[160];
  for (const Vec3& p : mesh.positions()) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  if (uv)
    for (const Vec2& t : *uv) {
      std::snprintf(line, sizeof line, "vt %.17g %.17g\n", t.x, t.y);
      out += line;
    }
  for (const Triangle& t : mesh.triangles()) {
    if (uv)
      std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1,
                    t[2] + 1);
    else std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += line;
  }
  return out;
}

}  // namespace straightest
