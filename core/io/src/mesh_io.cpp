// Reading a mesh (declared in mesh_io.hpp): the format from a name or from the bytes themselves, the
// file read into memory, then the OBJ, OFF, PLY or STL reader and TriMesh::build. The readers live in
// obj_reader.cpp, off_reader.cpp, ply_reader.cpp and stl_reader.cpp, the writer in obj_writer.cpp.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <sys/stat.h>

#include "obj_reader.hpp"
#include "off_reader.hpp"
#include "ply_reader.hpp"
#include "stl_reader.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/io/text_scan.hpp"

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

/// UTF-16 text: a byte-order mark, or ASCII with a NUL after (or before) each character.
bool looksUtf16(std::string_view bytes) {
  if (bytes.size() >= 2 && ((bytes[0] == '\xFF' && bytes[1] == '\xFE') || (bytes[0] == '\xFE' && bytes[1] == '\xFF')))
    return true;
  const size_t n = std::min<size_t>(bytes.size(), 64) & ~size_t{1};
  if (n < 4) return false;
  for (int zeroAt : {0, 1}) {
    bool pattern = true;
    for (size_t i = 0; i < n && pattern; i += 2)
      pattern = bytes[i + zeroAt] == 0 && bytes[i + 1 - zeroAt] != 0 &&
                static_cast<unsigned char>(bytes[i + 1 - zeroAt]) < 0x80;
    if (pattern) return true;
  }
  return false;
}

/// OFF when the first token (after comments and blank lines) is an OFF keyword, otherwise OBJ.
MeshFormat detectTextFormat(std::string_view bytes) {
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

/// The binary formats by their signatures, then OFF by its keyword, otherwise OBJ.
MeshFormat detectMeshFormat(std::string_view bytes) {
  if (looksLikePly(bytes)) return MeshFormat::Ply;
  if (looksLikeBinaryStl(bytes) || looksLikeAsciiStl(bytes)) return MeshFormat::Stl;
  return detectTextFormat(bytes);
}

Expected<MeshFormat> parseMeshFormat(std::string_view name) {
  const std::string n = lower(name);
  if (n == "obj") return MeshFormat::Obj;
  if (n == "off") return MeshFormat::Off;
  if (n == "ply") return MeshFormat::Ply;
  if (n == "stl") return MeshFormat::Stl;
  if (n == "auto" || n.empty()) return MeshFormat::Auto;
  return Error{ErrorCode::UnsupportedFormat,
               "unknown mesh format " + text::quoted(name) + " (use obj, off, ply, stl or auto)"};
}

MeshFormat meshFormatFromFileName(std::string_view name) {
  const std::string extension = lower(name.size() >= 4 ? name.substr(name.size() - 4) : std::string_view());
  for (const auto& [suffix, format] : {std::pair{".obj", MeshFormat::Obj}, std::pair{".off", MeshFormat::Off},
                                       std::pair{".ply", MeshFormat::Ply}, std::pair{".stl", MeshFormat::Stl}})
    if (extension == suffix) return format;
  return MeshFormat::Auto;
}

Expected<PolygonSoup> parsePolygonSoup(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  if (bytes.empty()) return Error{ErrorCode::Empty, "file is empty"};
  if (format == MeshFormat::Auto) format = detectMeshFormat(bytes);
  if (format == MeshFormat::Ply) return readPly(bytes, limits);
  if (format == MeshFormat::Stl) return readStl(bytes, limits);
  if (looksUtf16(bytes)) return Error{ErrorCode::UnsupportedFormat, "UTF-16 text is not supported: save as UTF-8"};
  if (looksBinary(bytes))
    return Error{ErrorCode::UnsupportedFormat,
                 "file contains binary data that is neither a binary PLY nor a binary STL; expected an OBJ, OFF, "
                 "PLY or STL mesh"};
  return format == MeshFormat::Off ? readOff(bytes, limits) : readObj(bytes, limits);
}

Expected<TriMesh> loadMesh(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  auto soup = parsePolygonSoup(bytes, format, limits);
  if (!soup) return soup.error();
  const int64_t polygons = soup.value().polygonsTriangulated;
  std::vector<std::string> notes = std::move(soup.value().notes);
  if (polygons > 0) notes.push_back(std::to_string(polygons) + " polygons with more than 3 corners were triangulated");
  return TriMesh::build(std::move(soup.value().positions), std::move(soup.value().triangles), limits, std::move(notes));
}

Expected<TriMesh> loadMeshFile(const std::string& path, const BuildLimits& limits) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return Error{ErrorCode::Io, "cannot open '" + path + "': " + std::strerror(errno)};
  // A directory opens for reading too, and its "size" would be taken for a file's.
  struct stat info {};
  if (fstat(fileno(file.get()), &info) == 0 && S_ISDIR(info.st_mode))
    return Error{ErrorCode::Io, "cannot read '" + path + "': it is a directory"};
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
