// Mesh readers. OFF: our own strict line-based parser. OBJ: tinyobjloader, preceded by one linear
// scan of our own that finds what tinyobjloader would silently accept or report without a line number
// (non-numeric or non-finite coordinates, faces with fewer than 3 corners, index 0) so every error
// names its line; tinyobjloader then reads only those checked "v"/"f" lines and the two readings
// must agree. Both formats share triangulatePolygon() and TriMesh::build().
#include "straightest/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

#include <fast_float/fast_float.h>

#include "tiny_obj_loader.h"

namespace straightest {
namespace {

constexpr size_t kMaxNumberChars = 64;  // longer numeric tokens are rejected (keeps strtod linear)

Error parseError(int64_t line, const std::string& what) {
  return Error{ErrorCode::Parse, "line " + std::to_string(line) + ": " + what};
}

std::string quoted(std::string_view token) {
  std::string s(token.substr(0, 40));
  for (char& c : s)
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  return "'" + s + (token.size() > 40 ? "...'" : "'");
}

/// Splits text into lines ending in "\n", "\r\n" or a lone "\r" (as tinyobjloader does, so both
/// readers see the same lines), calling fn(lineNumber, line) until fn returns false. Linear.
template <class Fn>
void forEachLine(std::string_view text, Fn&& fn) {
  int64_t number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    if (!fn(++number, text.substr(pos, end - pos))) return;
    pos = end + ((end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n') ? 2 : 1);
  }
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// Whitespace-separated tokens of a line (up to `max`; more are counted but not stored).
struct Tokens {
  std::vector<std::string_view> items;
  size_t count = 0;
};
void tokenize(std::string_view line, Tokens& out, size_t max = 64) {
  out.items.clear();
  out.count = 0;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    if (i >= line.size()) break;
    size_t j = i;
    while (j < line.size() && !isSpace(line[j])) ++j;
    if (out.count < max) out.items.push_back(line.substr(i, j - i));
    ++out.count;
    i = j;
  }
}

enum class NumberStatus { Ok, NotANumber, NonFinite, TooLong };

bool isPlainDecimal(std::string_view t);

NumberStatus parseDouble(std::string_view token, double& out) {
  if (token.size() > kMaxNumberChars) return NumberStatus::TooLong;
  // Plain decimals (nearly every coordinate) go through fast_float: correctly rounded like strtod, so
  // the same value, but several times faster (musl's strtod in WASM especially). Anything else
  // (hexadecimal floats, inf, nan) keeps strtod's reading and is judged by the callers as before.
  if (!token.empty() && isPlainDecimal(token)) {
    const char* first = token.data() + (token[0] == '+' ? 1 : 0);  // from_chars takes no '+'
    const char* last = token.data() + token.size();
    const auto r = fast_float::from_chars(first, last, out);
    if (r.ec != std::errc() || r.ptr != last) return NumberStatus::NotANumber;
    return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::NonFinite;
  }
  char buf[kMaxNumberChars + 1];
  std::memcpy(buf, token.data(), token.size());
  buf[token.size()] = 0;
  char* end = nullptr;
  out = std::strtod(buf, &end);
  if (end != buf + token.size() || token.empty()) return NumberStatus::NotANumber;
  if (!std::isfinite(out)) return NumberStatus::NonFinite;
  return NumberStatus::Ok;
}

/// [+-]? (digits [. digits*] | . digits) ([eE] [+-]? digits)? — the numbers tinyobjloader reads the
/// same way strtod does (it reads hexadecimal floats such as 0x1p3 as 0, silently).
bool isPlainDecimal(std::string_view t) {
  size_t i = 0;
  auto digits = [&] {
    const size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - start;
  };
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  size_t mantissa = digits();
  if (i < t.size() && t[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == t.size();
}

/// True when some number on the line has an exponent of more than 4 digits ("1e-2147483648").
bool longExponent(std::string_view line) {
  for (size_t i = 1; i < line.size(); ++i) {
    if ((line[i] != 'e' && line[i] != 'E') || !(std::isdigit(static_cast<unsigned char>(line[i - 1])) || line[i - 1] == '.'))
      continue;
    size_t j = i + 1;
    if (j < line.size() && (line[j] == '+' || line[j] == '-')) ++j;
    size_t digits = 0;
    while (j < line.size() && std::isdigit(static_cast<unsigned char>(line[j]))) ++j, ++digits;
    if (digits > 4) return true;
  }
  return false;
}

bool parseInt64(std::string_view token, int64_t& out) {
  if (token.empty() || token.size() > 19) return false;  // with a sign: at most 18 digits, no overflow
  size_t i = 0;
  bool negative = false;
  if (token[0] == '-' || token[0] == '+') { negative = token[0] == '-'; i = 1; }
  if (i == token.size() || token.size() - i > 18) return false;
  int64_t v = 0;
  for (; i < token.size(); ++i) {
    if (token[i] < '0' || token[i] > '9') return false;
    v = v * 10 + (token[i] - '0');
  }
  out = negative ? -v : v;
  return true;
}

std::string_view stripComment(std::string_view line) {
  const size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool looksBinary(std::string_view bytes) {
  const size_t n = std::min<size_t>(bytes.size(), 4096);
  for (size_t i = 0; i < n; ++i)
    if (bytes[i] == 0) return true;
  return false;
}

// ---------------------------------------------------------------- OFF

Expected<PolygonSoup> parseOff(std::string_view text, const BuildLimits& limits) {
  enum class Stage { Header, Counts, Vertices, Faces, Done } stage = Stage::Header;
  PolygonSoup soup;
  int64_t nv = 0, nf = 0, facesRead = 0;
  size_t extraPerVertex = 0;  // COFF: colour (3 or 4 values); NOFF: normal (3)
  std::vector<int32_t> polygon;
  Tokens tokens;
  std::optional<Error> error;
  size_t consumed = 0;

  auto handleCounts = [&](int64_t line, const std::vector<std::string_view>& items) -> bool {
    int64_t ne = 0;
    if (items.size() < 2 || items.size() > 3 || !parseInt64(items[0], nv) || !parseInt64(items[1], nf) ||
        (items.size() == 3 && !parseInt64(items[2], ne)) || nv < 0 || nf < 0 || ne < 0) {
      error = parseError(line, "expected the counts 'vertices faces [edges]' after the OFF keyword");
      return false;
    }
    if (nv > limits.maxVertices || nf > limits.maxFaces) {
      error = Error{ErrorCode::TooLarge, "line " + std::to_string(line) + ": header claims " + std::to_string(nv) +
                                             " vertices and " + std::to_string(nf) +
                                             " faces, over the limits of " + std::to_string(limits.maxVertices) +
                                             " vertices and " + std::to_string(limits.maxFaces) + " faces"};
      return false;
    }
    // Each vertex needs at least "0 0 0\n" (6 bytes) and each face line at least 2 bytes (a bound
    // loose enough that a short face line still gets its own, more precise error).
    const uint64_t remaining = text.size() - consumed;
    if (static_cast<uint64_t>(nv) * 6 + static_cast<uint64_t>(nf) * 2 > remaining) {
      error = parseError(line, "header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                                   " faces, but only " + std::to_string(remaining) +
                                   " bytes follow (the file is truncated or the header lies)");
      return false;
    }
    soup.positions.reserve(nv);
    soup.triangles.reserve(nf);
    stage = nv > 0 ? Stage::Vertices : (nf > 0 ? Stage::Faces : Stage::Done);
    return true;
  };

  forEachLine(text, [&](int64_t line, std::string_view raw) {
    consumed += raw.size() + 1;
    tokenize(stripComment(raw), tokens);
    if (tokens.count == 0) return true;
    auto& items = tokens.items;
    switch (stage) {
      case Stage::Header: {
        const std::string_view kw = items[0];
        if (kw != "OFF" && kw != "COFF" && kw != "NOFF") {
          error = Error{ErrorCode::UnsupportedFormat, "line " + std::to_string(line) +
                                                          ": expected the keyword OFF (or COFF, NOFF), found " +
                                                          quoted(kw)};
          return false;
        }
        extraPerVertex = kw == "COFF" ? 4 : kw == "NOFF" ? 3 : 0;
        stage = Stage::Counts;
        if (items.size() > 1) {
          std::vector<std::string_view> rest(items.begin() + 1, items.end());
          return handleCounts(line, rest);
        }
        return true;
      }
      case Stage::Counts: return handleCounts(line, items);
      case Stage::Vertices: {
        // OFF: exactly x y z. COFF: x y z and a colour of 3 or 4 values. NOFF: x y z and a normal.
        const bool countOk = extraPerVertex == 0 ? tokens.count == 3
                             : extraPerVertex == 4 ? (tokens.count == 6 || tokens.count == 7)
                                                   : tokens.count == 6;
        if (!countOk) {
          error = parseError(line, "vertex " + std::to_string(soup.positions.size()) + " has " +
                                       std::to_string(tokens.count) + " values, expected " +
                                       (extraPerVertex == 0 ? "3 (x y z)" : extraPerVertex == 4 ? "6 or 7 (x y z r g b [a])"
                                                                                                : "6 (x y z nx ny nz)"));
          return false;
        }
        double c[3];
        for (int k = 0; k < 3; ++k) {
          const NumberStatus st = parseDouble(items[k], c[k]);
          if (st == NumberStatus::NonFinite) {
            error = Error{ErrorCode::NonFinite, "line " + std::to_string(line) + ": vertex " +
                                                    std::to_string(soup.positions.size()) +
                                                    " has a non-finite coordinate " + quoted(items[k])};
            return false;
          }
          if (st != NumberStatus::Ok) {
            error = parseError(line, "vertex " + std::to_string(soup.positions.size()) + ": coordinate " +
                                         quoted(items[k]) + " is not a number");
            return false;
          }
        }
        soup.positions.push_back({c[0], c[1], c[2]});
        if (static_cast<int64_t>(soup.positions.size()) == nv) stage = nf > 0 ? Stage::Faces : Stage::Done;
        return true;
      }
      case Stage::Faces: {
        const int64_t face = facesRead;
        int64_t k = 0;
        if (!parseInt64(items[0], k) || k < 0) {
          error = parseError(line, "face " + std::to_string(face) + ": expected a vertex count, found " +
                                       quoted(items[0]));
          return false;
        }
        if (k < 3) {
          error = Error{ErrorCode::InvalidFace, "line " + std::to_string(line) + ": face " + std::to_string(face) +
                                                    " has " + std::to_string(k) + " vertices (at least 3 needed)"};
          return false;
        }
        if (static_cast<size_t>(k) + 1 > tokens.count) {
          error = parseError(line, "face " + std::to_string(face) + " announces " + std::to_string(k) +
                                       " vertices but lists " + std::to_string(tokens.count - 1));
          return false;
        }
        if (static_cast<size_t>(k) + 1 > items.size()) tokenize(stripComment(raw), tokens, k + 1 + 4);
        polygon.clear();
        for (int64_t j = 0; j < k; ++j) {
          int64_t index = 0;
          if (!parseInt64(items[1 + j], index)) {
            error = parseError(line, "face " + std::to_string(face) + ": vertex index " + quoted(items[1 + j]) +
                                         " is not an integer");
            return false;
          }
          if (index < 0 || index >= nv) {
            error = Error{ErrorCode::IndexOutOfRange,
                          "line " + std::to_string(line) + ": face " + std::to_string(face) + " refers to vertex " +
                              std::to_string(index) + ", but the file has " + std::to_string(nv) +
                              " vertices (valid: 0.." + std::to_string(nv - 1) + ")"};
            return false;
          }
          polygon.push_back(static_cast<int32_t>(index));
        }
        // Anything after the indices is a colour: it must be numeric.
        for (size_t j = static_cast<size_t>(k) + 1; j < items.size(); ++j) {
          double ignored;
          if (parseDouble(items[j], ignored) == NumberStatus::NotANumber) {
            error = parseError(line, "face " + std::to_string(face) + ": unexpected " + quoted(items[j]) +
                                         " after its vertex indices");
            return false;
          }
        }
        if (k == 3) {
          soup.triangles.push_back({polygon[0], polygon[1], polygon[2]});
        } else {
          triangulatePolygon(soup.positions, polygon, soup.triangles);
          ++soup.polygonsTriangulated;
        }
        if (++facesRead == nf) stage = Stage::Done;
        return true;
      }
      case Stage::Done:
        error = parseError(line, "unexpected content after the last face: " + quoted(raw));
        return false;
    }
    return true;
  });
  if (error) return *error;
  switch (stage) {
    case Stage::Header: return Error{ErrorCode::Empty, "file is empty (no OFF header)"};
    case Stage::Counts: return Error{ErrorCode::Parse, "file ends after the OFF keyword, before the counts"};
    case Stage::Vertices:
      return Error{ErrorCode::Parse, "file ends after " + std::to_string(soup.positions.size()) + " of " +
                                         std::to_string(nv) + " vertices (truncated?)"};
    case Stage::Faces:
      return Error{ErrorCode::Parse, "file ends after " + std::to_string(facesRead) + " of " + std::to_string(nf) +
                                         " faces (truncated?)"};
    case Stage::Done: break;
  }
  return soup;
}

// ---------------------------------------------------------------- OBJ

/// What our own pass over an OBJ reads: every coordinate (strtod, correctly rounded) and every face
/// corner's vertex index resolved to 0-based (negative = relative), with the line of each face.
struct ObjScan {
  std::vector<Vec3> positions;
  std::vector<int64_t> corners;      // resolved vertex index per corner
  std::vector<int64_t> faceStart{0};  // corners of face f: [faceStart[f], faceStart[f+1])
  std::vector<int64_t> faceLines;
  /// The checked "v" and "f" lines, reduced to what both readers must agree on (three coordinates;
  /// the vertex index of each corner), for tinyobjloader. It never sees the rest of the file: its
  /// readers of other statements ("vw", "vt", "l", "mtllib", ...) have overflowed on fuzzed input.
  std::string forTinyobj;
};

Expected<ObjScan> scanObj(std::string_view text) {
  ObjScan scan;
  std::optional<Error> error;
  Tokens tokens;
  forEachLine(text, [&](int64_t line, std::string_view raw) {
    size_t i = 0;
    while (i < raw.size() && (raw[i] == ' ' || raw[i] == '\t')) ++i;  // as tinyobjloader: space and tab only
    // Only "v " and "f " lines matter here; like tinyobjloader, only a space or tab ends the keyword.
    if (i + 1 >= raw.size() || (raw[i + 1] != ' ' && raw[i + 1] != '\t')) return true;
    const char kind = raw[i];
    if (kind != 'v' && kind != 'f') return true;
    if (kind == 'v' && longExponent(raw)) {
      // tinyobjloader's number reader overflows (undefined behaviour) on exponents this long.
      error = parseError(line, "a number has an exponent with more than 4 digits");
      return false;
    }
    tokenize(stripComment(raw.substr(i + 2)), tokens, 4);
    const int64_t vertex = static_cast<int64_t>(scan.positions.size());
    if (kind == 'v') {
      if (tokens.count < 3) {
        error = parseError(line, "vertex " + std::to_string(vertex) + " has " + std::to_string(tokens.count) +
                                     " coordinates, expected at least 3");
        return false;
      }
      double c[3];
      for (int k = 0; k < 3; ++k) {
        const NumberStatus st = parseDouble(tokens.items[k], c[k]);
        if (st == NumberStatus::NonFinite) {
          error = Error{ErrorCode::NonFinite, "line " + std::to_string(line) + ": vertex " + std::to_string(vertex) +
                                                  " has a non-finite coordinate " + quoted(tokens.items[k])};
          return false;
        }
        if (st != NumberStatus::Ok || !isPlainDecimal(tokens.items[k])) {
          error = parseError(line, "vertex " + std::to_string(vertex) + ": coordinate " + quoted(tokens.items[k]) +
                                       " is not a plain decimal number");
          return false;
        }
      }
      scan.positions.push_back({c[0], c[1], c[2]});
      scan.forTinyobj += 'v';
      for (int k = 0; k < 3; ++k) (scan.forTinyobj += ' ') += tokens.items[k];
      scan.forTinyobj += '\n';
      return true;
    }
    const int64_t face = static_cast<int64_t>(scan.faceLines.size());
    if (tokens.count < 3) {
      error = Error{ErrorCode::InvalidFace, "line " + std::to_string(line) + ": face " + std::to_string(face) +
                                                " has " + std::to_string(tokens.count) + " vertices (at least 3 needed)"};
      return false;
    }
    tokenize(stripComment(raw.substr(i + 2)), tokens, tokens.count);
    scan.forTinyobj += 'f';
    for (std::string_view corner : tokens.items) {
      int64_t index = 0;
      const std::string_view vertexIndex = corner.substr(0, corner.find('/'));
      (scan.forTinyobj += ' ') += vertexIndex;
      if (!parseInt64(vertexIndex, index)) {
        error = parseError(line, "face " + std::to_string(face) + ": vertex index " + quoted(corner) +
                                     " is not an integer (or too large)");
        return false;
      }
      const int64_t resolved = index > 0 ? index - 1 : vertex + index;
      if (index == 0 || resolved < 0 || resolved > std::numeric_limits<int32_t>::max()) {
        error = Error{ErrorCode::IndexOutOfRange,
                      "line " + std::to_string(line) + ": face " + std::to_string(face) + " uses vertex index " +
                          std::to_string(index) +
                          (index == 0 ? " (OBJ indices start at 1)"
                                      : " (" + std::to_string(vertex) + " vertices are defined before this line)")};
        return false;
      }
      scan.corners.push_back(resolved);
    }
    scan.forTinyobj += '\n';
    scan.faceStart.push_back(static_cast<int64_t>(scan.corners.size()));
    scan.faceLines.push_back(line);
    return true;
  });
  if (error) return *error;
  return scan;
}

/// tinyobjloader parses the file's checked v/f lines; our scan read the same numbers independently. Any disagreement (a
/// number one of them reads differently) is a parse error rather than a silently different mesh.
Expected<PolygonSoup> parseObj(std::string_view text, const BuildLimits& limits) {
  auto scanned = scanObj(text);
  if (!scanned) return scanned.error();
  const ObjScan& scan = scanned.value();
  const int64_t nv = static_cast<int64_t>(scan.positions.size());
  if (nv > limits.maxVertices)
    return Error{ErrorCode::TooLarge, "file has " + std::to_string(nv) + " vertices, over the limit of " +
                                          std::to_string(limits.maxVertices)};

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(scan.forTinyobj, std::string(), config)) {
    std::string message = reader.Error();
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back()))) message.pop_back();
    return Error{ErrorCode::Parse, "OBJ: " + (message.empty() ? std::string("cannot parse") : message)};
  }
  const auto& attrib = reader.GetAttrib();
  if (static_cast<int64_t>(attrib.vertices.size()) != 3 * nv)
    return Error{ErrorCode::Parse, "OBJ readers disagree on the number of vertices (" + std::to_string(nv) + " vs " +
                                       std::to_string(attrib.vertices.size() / 3) + "): malformed 'v' lines"};
  for (int64_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) {
      const double ours = scan.positions[v][k], theirs = attrib.vertices[3 * v + k];
      if (!(std::abs(ours - theirs) <= 1e-12 * std::max(std::abs(ours), std::abs(theirs)) + 1e-300))
        return Error{ErrorCode::Parse, "vertex " + std::to_string(v) + ": coordinate " + std::to_string(ours) +
                                           " is read as " + std::to_string(theirs) +
                                           " by tinyobjloader (an unusual number format); rewrite it plainly"};
    }

  PolygonSoup soup;
  soup.positions = scan.positions;
  std::vector<int32_t> polygon;
  int64_t face = 0, corner = 0;
  for (const auto& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (const auto count : shape.mesh.num_face_vertices) {
      const int64_t line = face < static_cast<int64_t>(scan.faceLines.size()) ? scan.faceLines[face] : -1;
      if (face >= static_cast<int64_t>(scan.faceLines.size()) ||
          scan.faceStart[face + 1] - scan.faceStart[face] != static_cast<int64_t>(count))
        return Error{ErrorCode::Parse, "line " + std::to_string(line) + ": OBJ readers disagree on face " +
                                           std::to_string(face)};
      polygon.clear();
      for (size_t j = 0; j < count; ++j, ++corner) {
        const int64_t index = scan.corners[corner];
        if (index != shape.mesh.indices[offset + j].vertex_index)
          return Error{ErrorCode::Parse, "line " + std::to_string(line) + ": OBJ readers disagree on face " +
                                             std::to_string(face) + "'s vertex index"};
        if (index >= nv)
          return Error{ErrorCode::IndexOutOfRange,
                       "line " + std::to_string(line) + ": face " + std::to_string(face) + " refers to vertex " +
                           std::to_string(index + 1) + " (1-based), but the file has " + std::to_string(nv) +
                           " vertices"};
        polygon.push_back(static_cast<int32_t>(index));
      }
      offset += count;
      if (polygon.size() == 3) {
        soup.triangles.push_back({polygon[0], polygon[1], polygon[2]});
      } else {
        triangulatePolygon(soup.positions, polygon, soup.triangles);
        ++soup.polygonsTriangulated;
      }
      ++face;
      if (static_cast<int64_t>(soup.triangles.size()) > limits.maxFaces)
        return Error{ErrorCode::TooLarge, "file has more than " + std::to_string(limits.maxFaces) + " faces"};
    }
  }
  if (face != static_cast<int64_t>(scan.faceLines.size()))
    return Error{ErrorCode::Parse, "OBJ readers disagree on the number of faces (" +
                                       std::to_string(scan.faceLines.size()) + " vs " + std::to_string(face) + ")"};
  if (nv == 0 && soup.triangles.empty())
    return Error{ErrorCode::UnsupportedFormat, "found neither an OFF header nor OBJ 'v'/'f' lines"};
  return soup;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

Expected<MeshFormat> parseMeshFormat(std::string_view name) {
  const std::string n = lower(name);
  if (n == "obj") return MeshFormat::Obj;
  if (n == "off") return MeshFormat::Off;
  if (n == "auto" || n.empty()) return MeshFormat::Auto;
  return Error{ErrorCode::UnsupportedFormat, "unknown mesh format " + quoted(name) + " (use obj, off or auto)"};
}

Expected<PolygonSoup> parsePolygonSoup(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  if (bytes.empty()) return Error{ErrorCode::Empty, "file is empty"};
  if (looksBinary(bytes))
    return Error{ErrorCode::UnsupportedFormat, "file contains binary data; expected a text OBJ or OFF mesh"};
  if (format == MeshFormat::Auto) {
    // OFF if the first token (after comments and blank lines) is OFF, COFF or NOFF.
    format = MeshFormat::Obj;
    forEachLine(bytes, [&](int64_t, std::string_view line) {
      Tokens t;
      tokenize(stripComment(line), t, 1);
      if (t.count == 0) return true;
      const std::string_view kw = t.items[0];
      if (kw.substr(0, 3) == "OFF" || kw == "COFF" || kw == "NOFF") format = MeshFormat::Off;
      return false;
    });
  }
  return format == MeshFormat::Off ? parseOff(bytes, limits) : parseObj(bytes, limits);
}

Expected<TriMesh> loadMesh(std::string_view bytes, MeshFormat format, const BuildLimits& limits) {
  auto soup = parsePolygonSoup(bytes, format, limits);
  if (!soup) return soup.error();
  const int64_t polygons = soup.value().polygonsTriangulated;
  std::vector<std::string> notes;
  if (polygons > 0) notes.push_back(std::to_string(polygons) + " polygons with more than 3 corners were triangulated");
  return TriMesh::build(std::move(soup.value().positions), std::move(soup.value().triangles), limits,
                        std::move(notes));
}

Expected<TriMesh> loadMeshFile(const std::string& path, const BuildLimits& limits) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorCode::Io, "cannot open '" + path + "': " + std::strerror(errno)};
  // Read in blocks (streaming the rdbuf into a stringstream goes character by character: ~1 ms per
  // 100 KB natively and several times that in WASM).
  std::string content;
  std::vector<char> block(1 << 20);
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    content.append(block.data(), static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) return Error{ErrorCode::Io, "cannot read '" + path + "'"};
  const std::string ext = lower(path.size() >= 4 ? std::string_view(path).substr(path.size() - 4) : "");
  const MeshFormat format = ext == ".obj" ? MeshFormat::Obj : ext == ".off" ? MeshFormat::Off : MeshFormat::Auto;
  return loadMesh(content, format, limits);
}

std::string writeObj(const TriMesh& mesh, const std::vector<Vec2>* uv) {
  std::string out = "# written by straightest\n";
  char line[160];
  for (const Vec3& p : mesh.positions()) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  if (uv)
    for (const Vec2& t : *uv) {
      std::snprintf(line, sizeof line, "vt %.17g %.17g\n", t[0], t[1]);
      out += line;
    }
  for (const Triangle& t : mesh.triangles()) {
    if (uv)
      std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1, t[2] + 1);
    else
      std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += line;
  }
  return out;
}

void triangulatePolygon(const std::vector<Vec3>& positions, const std::vector<int32_t>& polygon,
                        std::vector<Triangle>& out) {
  const size_t n = polygon.size();
  auto fan = [&](size_t from, const std::vector<int32_t>& ring) {
    for (size_t i = from + 1; i + 1 < ring.size(); ++i) out.push_back({ring[from], ring[i], ring[i + 1]});
  };
  if (n < 3) return;
  // Ear clipping is quadratic; very large polygons (never seen in practice) take the fan.
  if (n == 3 || n > 256) { fan(0, polygon); return; }
  // Newell normal and a 2D frame in its plane.
  Vec3 normal;
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = positions[polygon[i]];
    const Vec3& b = positions[polygon[(i + 1) % n]];
    normal += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  normal = normalized(normal);
  if (squaredNorm(normal) == 0) { fan(0, polygon); return; }
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(normal, helper)), w = cross(normal, u);
  std::vector<int32_t> ring(polygon);
  std::vector<std::array<double, 2>> p;
  p.reserve(n);
  for (int32_t v : ring) p.push_back({dot(positions[v], u), dot(positions[v], w)});
  std::vector<size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  auto cross2 = [&](size_t a, size_t b, size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };
  while (idx.size() > 3) {
    bool clipped = false;
    const size_t m = idx.size();
    for (size_t i = 0; i < m && !clipped; ++i) {
      const size_t a = idx[(i + m - 1) % m], b = idx[i], c = idx[(i + 1) % m];
      if (cross2(a, b, c) <= 0) continue;  // reflex or flat corner (the Newell frame makes the polygon CCW)
      bool empty = true;
      for (size_t j = 0; j < m && empty; ++j) {
        const size_t q = idx[j];
        if (q == a || q == b || q == c) continue;
        if (cross2(a, b, q) >= 0 && cross2(b, c, q) >= 0 && cross2(c, a, q) >= 0) empty = false;
      }
      if (!empty) continue;
      out.push_back({ring[a], ring[b], ring[c]});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  std::vector<int32_t> rest;
  for (size_t i : idx) rest.push_back(ring[i]);
  fan(0, rest);
}

}  // namespace straightest
