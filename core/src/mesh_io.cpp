// Reading a mesh (declared in mesh_io.hpp): the format from a name or from the bytes themselves, the
// file read into memory, then the OBJ or OFF reader and TriMesh::build. The readers live in
// obj_reader.cpp and off_reader.cpp, the writer in obj_writer.cpp.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "obj_reader.hpp"
#include "off_reader.hpp"
#include "straightest/mesh_io.hpp"
#include "text_scan.hpp"

namespace straightest {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// A NUL byte in the first 4 KB: a binary file (binary STL or PLY, UTF-16 text, an image...).
bool looksBinary(std::string_view bytes) {
  const size_t n = std::min<size_t>(bytes.size(), 4096);
  for (size_t i = 0; i < n; ++i)
    if (bytes[i] == 0) return true;
  return false;
}

/// OFF when the first token (after comments and blank lines) is an OFF keyword, otherwise OBJ.
MeshFormat detectFormat(std::string_view bytes) {
  MeshFormat format = MeshFormat::Obj;
  text::forEachLine(bytes, [&](int64_t, std::string_view line) {
    text::Tokens t;
    text::tokenize(text::stripComment(line), t, 1);
    if (t.count == 0) return true;
    const std::string_view keyword = t.items[0];
    if (keyword.substr(0, 3) == "OFF" || keyword == "COFF" || keyword == "NOFF") format = MeshFormat::Off;
    return false;
  });
  return format;
}

}  // namespace

Expected<MeshFormat> parseMeshFormat(std::string_view name) {
  const std::string n = lower(name);
  if (n == "obj") return MeshFormat::Obj;
  if (n == "off") return MeshFormat::Off;
  if (n == "auto" || n.empty()) return MeshFormat::Auto;
  return Error{ErrorCode::UnsupportedFormat, "unknown mesh format " + text::quoted(name) + " (use obj, off or auto)"};
}

MeshFormat meshFormatFromFileName(std::string_view name) {
  const std::string extension = lower(name.size() >= 4 ? name.substr(name.size() - 4) : std::string_view());
  return extension == ".obj" ? MeshFormat::Obj : extension == ".off" ? MeshFormat::Off : MeshFormat::Auto;
}

Expected<PolygonSoup> parsePolygonSoup(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  if (bytes.empty()) return Error{ErrorCode::Empty, "file is empty"};
  if (looksBinary(bytes))
    return Error{ErrorCode::UnsupportedFormat, "file contains binary data; expected a text OBJ or OFF mesh"};
  if (format == MeshFormat::Auto) format = detectFormat(bytes);
  return format == MeshFormat::Off ? readOff(bytes, limits) : readObj(bytes, limits);
}

Expected<TriMesh> loadMesh(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  auto soup = parsePolygonSoup(bytes, format, limits);
  if (!soup) return soup.error();
  const int64_t polygons = soup.value().polygonsTriangulated;
  std::vector<std::string> notes;
  if (polygons > 0) notes.push_back(std::to_string(polygons) + " polygons with more than 3 corners were triangulated");
  return TriMesh::build(std::move(soup.value().positions), std::move(soup.value().triangles), limits, std::move(notes));
}

Expected<TriMesh> loadMeshFile(const std::string& path, const BuildLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::Io, "cannot open '" + path + "': " + std::strerror(errno)};
  // Read in blocks (streaming the rdbuf into a stringstream goes character by character: ~1 ms per
  // 100 KB natively and several times that in WASM).
  std::string content;
  in.seekg(0, std::ios::end);
  if (const std::streamoff size = in.tellg(); size > 0) content.reserve(static_cast<size_t>(size));
  in.seekg(0, std::ios::beg);
  std::vector<char> block(1 << 20);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    content.append(block.data(), static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) return Error{ErrorCode::Io, "cannot read '" + path + "'"};
  return loadMesh(content, meshFormatFromFileName(path), limits);
}

}  // namespace straightest
