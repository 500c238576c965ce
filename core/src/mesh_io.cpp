// Reading a mesh (declared in mesh_io.hpp): the format from a name or from the bytes themselves, the
// file read into memory, then the OBJ or OFF reader and TriMesh::build. The readers live in
// obj_reader.cpp and off_reader.cpp, the writer in obj_writer.cpp.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return Error{ErrorCode::Io, "cannot open '" + path + "': " + std::strerror(errno)};
  // The whole file into one uninitialized buffer, read straight into it: one fread when the size is
  // known (a stream would copy every block once more, and a string would zero the buffer first), in
  // doubling steps when it is not (a pipe).
  long size = std::fseek(file.get(), 0, SEEK_END) == 0 ? std::ftell(file.get()) : -1;
  if (size < 0 || std::fseek(file.get(), 0, SEEK_SET) != 0) size = 0;
  size_t capacity = static_cast<size_t>(size) + 1, length = 0;  // +1: a known size is confirmed by reading 0 more
  std::unique_ptr<char[]> content(new char[capacity]);          // too large: bad_alloc, which the edges map (guarded)
  for (;;) {
    length += std::fread(content.get() + length, 1, capacity - length, file.get());
    if (length < capacity) break;
    std::unique_ptr<char[]> larger(new char[2 * capacity]);
    std::memcpy(larger.get(), content.get(), length);
    content = std::move(larger);
    capacity *= 2;
  }
  if (std::ferror(file.get())) return Error{ErrorCode::Io, "cannot read '" + path + "'"};
  file.reset();
  return loadMesh(std::string_view(content.get(), length), meshFormatFromFileName(path), limits);
}

}  // namespace straightest
