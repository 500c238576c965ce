// mesh_io.hpp — reading meshes from OBJ and OFF, from a file path or from bytes in memory (the
// browser hands bytes), and writing OBJ.
//
// OBJ goes through tinyobjloader (positions only; `vt`/`vn` and materials are ignored); OFF through a
// small strict parser of our own that tolerates `#` comments and blank lines. Polygons are split into
// triangles by ear clipping in the polygon's best-fit plane. Every error names its line (and face or
// vertex). Hostile input is bounded: counts in a header are checked against the caps and against the
// bytes that are left before anything is allocated, and every pass is linear in the input size.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "straightest/error.hpp"
#include "straightest/trimesh.hpp"

namespace straightest {

enum class MeshFormat { Auto, Obj, Off };

/// "obj", "off" or "auto" (case-insensitive) → MeshFormat; anything else → UnsupportedFormat error.
Expected<MeshFormat> parseMeshFormat(std::string_view name);

/// Raw polygon soup as read from a file, before validation.
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  int64_t polygonsTriangulated = 0;  // faces with more than 3 corners that were split
};

/// Parses bytes. Auto detects OFF by its header keyword and otherwise tries OBJ.
Expected<PolygonSoup> parsePolygonSoup(std::string_view bytes, MeshFormat format = MeshFormat::Auto,
                                       const BuildLimits& limits = {});

/// Parses and builds a TriMesh (see TriMesh::build for the validation).
Expected<TriMesh> loadMesh(std::string_view bytes, MeshFormat format = MeshFormat::Auto,
                           const BuildLimits& limits = {});

/// Reads a file; the format comes from the extension (.obj/.off), or from the content when unknown.
Expected<TriMesh> loadMeshFile(const std::string& path, const BuildLimits& limits = {});

/// OBJ text of the mesh, vertices in the mesh's order; with uv (one per vertex), a `vt` per vertex and
/// faces written as v/vt.
std::string writeObj(const TriMesh& mesh, const std::vector<Vec2>* uv = nullptr);

/// Splits one polygon (indices into positions) into triangles by ear clipping in its Newell plane;
/// falls back to a fan when the polygon is too degenerate to clip. Appends to `out`.
void triangulatePolygon(const std::vector<Vec3>& positions, const std::vector<int32_t>& polygon,
                        std::vector<Triangle>& out);

}  // namespace straightest
