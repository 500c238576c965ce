// The OFF reader (see off_reader.hpp): a line-based state machine — keyword, counts, vertices, faces —
// whose common vertex and face lines are read in place from the bytes (one pass, nothing allocated
// per line); every other line, and every error, goes through the state machine's strict reading.
#include "off_reader.hpp"

#include <optional>

#include "straightest/io/text_scan.hpp"
#include "straightest/mesh/polygon_triangulation.hpp"

namespace straightest {

using text::NumberStatus;
using text::parseDouble;
using text::parseError;
using text::parseInt64;
using text::quoted;
using text::stripComment;
using text::tokenize;
using text::Tokens;

namespace {

// The fast path for the common vertex line ("x y z") and face line ("k i1 ... ik"), read in place
// straight from the bytes: anything else on the line (a comment, a colour, a normal), and every error,
// is left to the state machine's own reading of that line, which gives the same result for what the
// fast path accepts. Each returns where the next line starts, or nullptr (and adds nothing).

const char* readVertexInPlace(const char* p, const char* end, Vec3& out) {
  double c[3];
  for (double& x : c) {
    p = text::skipInlineSpace(p, end);
    if (!text::readDecimalInPlace(p, end, x)) return nullptr;
  }
  out = {c[0], c[1], c[2]};
  return text::nextLineAt(text::skipInlineSpace(p, end), end);
}

const char* readFaceInPlace(const char* p, const char* end, int64_t vertices, std::vector<int32_t>& polygon) {
  int64_t corners = 0;
  if (!text::readCountInPlace(p = text::skipInlineSpace(p, end), end, corners) || corners < 3) return nullptr;
  polygon.clear();
  for (int64_t k = 0; k < corners; ++k) {
    int64_t index = 0;
    if (!text::readCountInPlace(p = text::skipInlineSpace(p, end), end, index) || index >= vertices) return nullptr;
    polygon.push_back(static_cast<int32_t>(index));
  }
  return text::nextLineAt(text::skipInlineSpace(p, end), end);
}

}  // namespace

Expected<PolygonSoup> readOff(std::string_view text, const BuildLimits& limits) {
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
                                             " vertices and " + std::to_string(nf) + " faces, over the limits of " +
                                             std::to_string(limits.maxVertices) + " vertices and " +
                                             std::to_string(limits.maxFaces) + " faces"};
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

  auto addPolygon = [&] {
    if (polygon.size() == 3) {
      soup.triangles.push_back({polygon[0], polygon[1], polygon[2]});
    } else {
      triangulatePolygon(soup.positions, polygon, soup.triangles);
      ++soup.polygonsTriangulated;
    }
  };

  // One line, read strictly: the header, the counts, and any vertex or face line the fast path left.
  auto readLine = [&](int64_t line, std::string_view raw) {
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
        const bool countOk = extraPerVertex == 0   ? tokens.count == 3
                             : extraPerVertex == 4 ? (tokens.count == 6 || tokens.count == 7)
                                                   : tokens.count == 6;
        if (!countOk) {
          error = parseError(line, "vertex " + std::to_string(soup.positions.size()) + " has " +
                                       std::to_string(tokens.count) + " values, expected " +
                                       (extraPerVertex == 0   ? "3 (x y z)"
                                        : extraPerVertex == 4 ? "6 or 7 (x y z r g b [a])"
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
          error = parseError(line,
                             "face " + std::to_string(face) + ": expected a vertex count, found " + quoted(items[0]));
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
        addPolygon();
        if (++facesRead == nf) stage = Stage::Done;
        return true;
      }
      case Stage::Done:
        error = parseError(line, "unexpected content after the last face: " + quoted(raw));
        return false;
    }
    return true;
  };

  const char* const end = text.data() + text.size();
  int64_t line = 0;
  for (const char* p = text.data(); p < end;) {
    ++line;
    const char* next = nullptr;
    if (stage == Stage::Vertices && extraPerVertex == 0) {
      Vec3 position;
      if ((next = readVertexInPlace(p, end, position))) {
        soup.positions.push_back(position);
        if (static_cast<int64_t>(soup.positions.size()) == nv) stage = nf > 0 ? Stage::Faces : Stage::Done;
      }
    } else if (stage == Stage::Faces && (next = readFaceInPlace(p, end, nv, polygon))) {
      addPolygon();
      if (++facesRead == nf) stage = Stage::Done;
    }
    if (next) {
      p = next;
      continue;
    }
    const size_t at = static_cast<size_t>(p - text.data());
    const size_t lineEnd = text::lineEnd(text, at);
    if (!readLine(line, text.substr(at, lineEnd - at))) break;
    p = text.data() + lineEnd;
    if (p < end) p += (*p == '\r' && p + 1 < end && p[1] == '\n') ? 2 : 1;
  }
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

}  // namespace straightest
