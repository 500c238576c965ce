// The OBJ writer (declared in mesh_io.hpp): a mesh, and optionally one texture coordinate per vertex,
// as OBJ text. Coordinates are written with 17 significant digits, so reading the file back gives
// exactly the same doubles; vertices keep the mesh's order, so `vt` k belongs to vertex k. With a uv per
// face corner (a cut mesh's map) each distinct uv is one `vt`, in the order faces first use it.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_map>

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

std::string writeObjWithCornerUv(const TriMesh& mesh, const std::vector<Vec2>& cornerUv) {
  std::string out = "# written by straightest (a vt per distinct corner uv: seams split)\n";
  char line[160];
  for (const Vec3& p : mesh.positions()) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  // Distinct by exact value (bit pattern, with +0 and −0 as one): the copies of a vertex on one side of
  // a seam carry the very same doubles, the two sides different ones.
  struct Key {
    uint64_t x, y;
    bool operator==(const Key& o) const { return x == o.x && y == o.y; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const { return std::hash<uint64_t>()(k.x * 0x9E3779B97F4A7C15ull ^ k.y); }
  };
  const auto bits = [](double d) {
    if (d == 0) d = 0;  // −0 → +0
    uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
  };
  const size_t nf = static_cast<size_t>(mesh.numFaces());
  const bool usable = cornerUv.size() == 3 * nf;
  std::unordered_map<Key, int32_t, KeyHash> index;
  std::vector<int32_t> vt(3 * nf, 0);  // 1-based vt per corner; 0: the face is written without vt
  for (size_t f = 0; usable && f < nf; ++f) {
    bool finite = true;
    for (int k = 0; k < 3; ++k) finite = finite && isFinite(cornerUv[3 * f + k]);
    if (!finite) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec2& t = cornerUv[3 * f + k];
      const auto [it, added] = index.emplace(Key{bits(t.x), bits(t.y)}, static_cast<int32_t>(index.size()) + 1);
      if (added) {
        std::snprintf(line, sizeof line, "vt %.17g %.17g\n", t.x, t.y);
        out += line;
      }
      vt[3 * f + k] = it->second;
    }
  }
  for (size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangle(static_cast<int32_t>(f));
    if (vt[3 * f] > 0)
      std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", t[0] + 1, vt[3 * f], t[1] + 1, vt[3 * f + 1], t[2] + 1,
                    vt[3 * f + 2]);
    else std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += line;
  }
  return out;
}

}  // namespace straightest
