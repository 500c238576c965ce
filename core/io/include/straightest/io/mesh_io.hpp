// mesh_io.hpp — meshes in and out of files: reading OBJ, OFF, PLY and STL from a file path or from
// bytes in memory (the browser hands bytes), choosing the format, and writing OBJ.
//
// Every reader is our own (core/src/obj_reader.cpp, off_reader.cpp, ply_reader.cpp, stl_reader.cpp;
// PLY and STL are described in their headers). The text readers make one pass over the bytes,
// strict about numbers (finite plain decimals, correctly rounded), and every error names its line (and
// face or vertex). For OBJ only positions and faces are read (`vt`, `vn`, groups and materials are
// skipped). Polygons are split into triangles (polygon_triangulation.hpp). Hostile input is bounded:
// counts in a header are checked against the caps and against the bytes that are left before anything
// is allocated, and every pass is linear in the input size.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "straightest/base/error.hpp"
#include "straightest/base/names.hpp"
#include "straightest/mesh/polygon_triangulation.hpp"
#include "straightest/mesh/trimesh.hpp"

namespace straightest {

enum class MeshFormat { Auto, Obj, Off, Ply, Stl };
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<MeshFormat> kMeshFormatNames[] = {{MeshFormat::Obj, "obj"},
                                                            {MeshFormat::Off, "off"},
                                                            {MeshFormat::Ply, "ply"},
                                                            {MeshFormat::Stl, "stl"},
                                                            {MeshFormat::Auto, "auto"}};

/// "obj", "off", "ply", "stl" or "auto" (case-insensitive; "" is auto) → MeshFormat; anything else → UnsupportedFormat.
Expected<MeshFormat> parseMeshFormat(std::string_view name);

/// The format a file name (or path) announces: ".obj", ".off", ".ply", ".stl" (any case), otherwise Auto
/// (let the content decide).
MeshFormat meshFormatFromFileName(std::string_view name);

/// Raw polygon soup as read from a file, before validation.
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  int64_t polygonsTriangulated = 0;  // faces with more than 3 corners that were split
  std::vector<std::string> notes;    // what the reader changed (e.g. STL triangles dropped by welding)
};

/// The format of a file's bytes as Auto reads them (see parsePolygonSoup).
MeshFormat detectMeshFormat(std::string_view bytes);

/// Parses bytes. Auto detects PLY by its magic line, binary STL by its size (84 + 50 per triangle),
/// ASCII STL by `solid`, OFF by its header keyword, and otherwise reads OBJ; UTF-16 text and other
/// binary data are rejected as such.
Expected<PolygonSoup> parsePolygonSoup(std::string_view bytes, MeshFormat format = MeshFormat::Auto,
                                       const BuildLimits& limits = {});

/// Parses and builds a TriMesh (see TriMesh::build for the validation).
Expected<TriMesh> loadMesh(std::string_view bytes, MeshFormat format = MeshFormat::Auto,
                           const BuildLimits& limits = {});

/// Reads a file; the format comes from its name (meshFormatFromFileName), or from the content.
Expected<TriMesh> loadMeshFile(const std::string& path, const BuildLimits& limits = {});

/// OBJ text of the mesh, vertices in the mesh's order; with uv (one per vertex), a `vt` per vertex and
/// faces written as v/vt. Reading it back gives the same doubles.
std::string writeObj(const TriMesh& mesh, const std::vector<Vec2>* uv = nullptr);

/// OBJ text with a uv per face corner (cornerUv[3f + k], e.g. Parameterization::cornerUv): one `vt` per
/// distinct uv, so a seam splits (`f v/vt` with different vt on its two sides); a face whose corners are
/// NaN (outside the parameterized component) is written without vt.
std::string writeObjWithCornerUv(const TriMesh& mesh, const std::vector<Vec2>& cornerUv);

/// The uv of every corner of an OBJ file's triangles, 3 per `f` line in file order (corner k of face f at
/// 3f + k; NaN for a corner without vt), as writeObjWithCornerUv writes them: reading its output gives
/// the same doubles. Errors: Parse (a polygon that is not a triangle, a missing or malformed vt).
Expected<std::vector<Vec2>> readObjCornerUv(std::string_view bytes);

}  // namespace straightest
