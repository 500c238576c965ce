// Shared by fuzz_obj, fuzz_off, fuzz_ply and fuzz_stl: parse bytes, check the error or the mesh, round-trip the mesh.
#pragma once
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "straightest/io/mesh_io.hpp"

namespace fuzz {

inline std::string writeOff(const TriMesh& m) {
  std::string out = "OFF\n" + std::to_string(m.numVertices()) + " " + std::to_string(m.numFaces()) + " 0\n";
  char line[128];
  for (const Vec3& p : m.positions()) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const Triangle& t : m.triangles()) {
    std::snprintf(line, sizeof line, "3 %d %d %d\n", t[0], t[1], t[2]);
    out += line;
  }
  return out;
}

/// `again` is a mesh re-read from text written from `m` with 17 significant digits: same connectivity
/// (already consistently oriented, so nothing may flip) and exactly the same positions (both readers
/// round decimals correctly).
inline void checkRoundTrip(const TriMesh& m, const Expected<TriMesh>& again, const char* what) {
  FUZZ_CHECK(again.ok(), "%s round trip failed: %s: %s", what, errorCodeName(again.error().code),
             again.error().message.c_str());
  const TriMesh& r = again.value();
  FUZZ_CHECK(r.numVertices() == m.numVertices() && r.numFaces() == m.numFaces(), "%s round trip: counts changed", what);
  FUZZ_CHECK(r.summary().reorientedFaces == 0, "%s round trip flipped %lld faces of a consistently oriented mesh", what,
             (long long)r.summary().reorientedFaces);
  for (int32_t f = 0; f < m.numFaces(); ++f)
    FUZZ_CHECK(r.triangle(f) == m.triangle(f), "%s round trip: face %d changed", what, f);
  for (int32_t v = 0; v < m.numVertices(); ++v) {
    const Vec3 &a = m.position(v), &b = r.position(v);
    for (int k = 0; k < 3; ++k) {
      FUZZ_CHECK(a[k] == b[k], "%s round trip: vertex %d coordinate %d %.17g -> %.17g", what, v, k, a[k], b[k]);
    }
  }
  FUZZ_CHECK(r.summary().eulerCharacteristic == m.summary().eulerCharacteristic &&
                 r.summary().boundaryLoopSizes == m.summary().boundaryLoopSizes,
             "%s round trip: topology changed", what);
}

inline void checkParse(std::string_view bytes, MeshFormat format) {
  const char* where = format == MeshFormat::Obj   ? "OBJ"
                      : format == MeshFormat::Off ? "OFF"
                      : format == MeshFormat::Ply ? "PLY"
                                                  : "STL";
  auto soup = parsePolygonSoup(bytes, format);
  auto mesh = loadMesh(bytes, format);
  if (!soup.ok()) {
    checkError(soup.error(), where);
    FUZZ_CHECK(!mesh.ok(), "%s: loadMesh succeeded where parsePolygonSoup failed", where);
    FUZZ_CHECK(mesh.error().code == soup.error().code && mesh.error().message == soup.error().message,
               "%s: loadMesh and parsePolygonSoup disagree", where);
    return;
  }
  const PolygonSoup& s = soup.value();
  // The parsers check indices themselves: a soup never refers to a missing vertex.
  for (size_t f = 0; f < s.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      FUZZ_CHECK(s.triangles[f][k] >= 0 && static_cast<size_t>(s.triangles[f][k]) < s.positions.size(),
                 "%s: soup triangle %zu refers to vertex %d of %zu", where, f, s.triangles[f][k], s.positions.size());
  for (size_t v = 0; v < s.positions.size(); ++v)
    FUZZ_CHECK(isFinite(s.positions[v]), "%s: soup vertex %zu is not finite", where, v);
  FUZZ_CHECK(s.polygonsTriangulated >= 0 && static_cast<size_t>(s.polygonsTriangulated) <= s.triangles.size(),
             "%s: polygonsTriangulated", where);
  checkBuildResult(s.positions, s.triangles, mesh, where);
  if (!mesh.ok()) return;
  const TriMesh& m = mesh.value();
  checkRoundTrip(m, loadMesh(writeOff(m), MeshFormat::Off), "OFF");
  checkRoundTrip(m, loadMesh(writeObj(m), MeshFormat::Obj), "OBJ");
  std::vector<Vec2> uv(m.numVertices());
  for (int32_t v = 0; v < m.numVertices(); ++v) uv[v] = {0.25 * v, 1.0 / (v + 1)};
  checkRoundTrip(m, loadMesh(writeObj(m, &uv), MeshFormat::Obj), "OBJ+uv");
}

}  // namespace fuzz
