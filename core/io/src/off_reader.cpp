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

/// The state machine: keyword, counts, vertices, faces. One line at a time, each read in place where it
/// is the common kind and strictly otherwise; the first error stops it.
class OffReader {
 public:
  OffReader(std::string_view text, const BuildLimits& limits) : text_(text), limits_(limits) {}

  Expected<PolygonSoup> read() {
    const char* const end = text_.data() + text_.size();
    int64_t line = 0;
    for (const char* p = text_.data(); p < end;) {
      ++line;
      const char* next = readInPlace(p, end);
      if (next) {
        p = next;
        continue;
      }
      const size_t at = static_cast<size_t>(p - text_.data());
      const size_t lineEnd = text::lineEnd(text_, at);
      if (!readLine(line, text_.substr(at, lineEnd - at))) break;
      p = text_.data() + lineEnd;
      if (p < end) p += (*p == '\r' && p + 1 < end && p[1] == '\n') ? 2 : 1;
    }
    if (error_) return *error_;
    return finish();
  }

 private:
  enum class Stage { Header, Counts, Vertices, Faces, Done };

  /// The fast path: a plain vertex or face line read from the bytes; where the next line starts, or nullptr.
  const char* readInPlace(const char* p, const char* end) {
    const char* next = nullptr;
    if (stage_ == Stage::Vertices && extraPerVertex_ == 0) {
      Vec3 position;
      if ((next = readVertexInPlace(p, end, position))) {
        soup_.positions.push_back(position);
        if (static_cast<int64_t>(soup_.positions.size()) == nv_) stage_ = nf_ > 0 ? Stage::Faces : Stage::Done;
      }
    } else if (stage_ == Stage::Faces && (next = readFaceInPlace(p, end, nv_, polygon_))) {
      addPolygon();
      if (++facesRead_ == nf_) stage_ = Stage::Done;
    }
    return next;
  }

  /// Where the file ended: the soup, or what was still missing.
  Expected<PolygonSoup> finish() {
    switch (stage_) {
      case Stage::Header: return Error{ErrorCode::Empty, "file is empty (no OFF header)"};
      case Stage::Counts: return Error{ErrorCode::Parse, "file ends after the OFF keyword, before the counts"};
      case Stage::Vertices:
        return Error{ErrorCode::Parse, "file ends after " + std::to_string(soup_.positions.size()) + " of " +
                                           std::to_string(nv_) + " vertices (truncated?)"};
      case Stage::Faces:
        return Error{ErrorCode::Parse, "file ends after " + std::to_string(facesRead_) + " of " + std::to_string(nf_) +
                                           " faces (truncated?)"};
      case Stage::Done: break;
    }
    return std::move(soup_);
  }

  bool fail(Error error) {
    error_ = std::move(error);
    return false;
  }

  bool handleCounts(int64_t line, const std::vector<std::string_view>& items) {
    int64_t ne = 0;
    if (items.size() < 2 || items.size() > 3 || !parseInt64(items[0], nv_) || !parseInt64(items[1], nf_) ||
        (items.size() == 3 && !parseInt64(items[2], ne)) || nv_ < 0 || nf_ < 0 || ne < 0)
      return fail(parseError(line, "expected the counts 'vertices faces [edges]' after the OFF keyword"));
    if (nv_ > limits_.maxVertices || nf_ > limits_.maxFaces)
      return fail(Error{ErrorCode::TooLarge, "line " + std::to_string(line) + ": header claims " + std::to_string(nv_) +
                                                 " vertices and " + std::to_string(nf_) +
                                                 " faces, over the limits of " + std::to_string(limits_.maxVertices) +
                                                 " vertices and " + std::to_string(limits_.maxFaces) + " faces"});
    // Each vertex needs at least "0 0 0\n" (6 bytes) and each face line at least 2 bytes (a bound
    // loose enough that a short face line still gets its own, more precise error).
    const uint64_t remaining = text_.size() - consumed_;
    if (static_cast<uint64_t>(nv_) * 6 + static_cast<uint64_t>(nf_) * 2 > remaining)
      return fail(parseError(line, "header claims " + std::to_string(nv_) + " vertices and " + std::to_string(nf_) +
                                       " faces, but only " + std::to_string(remaining) +
                                       " bytes follow (the file is truncated or the header lies)"));
    soup_.positions.reserve(nv_);
    soup_.triangles.reserve(nf_);
    stage_ = nv_ > 0 ? Stage::Vertices : (nf_ > 0 ? Stage::Faces : Stage::Done);
    return true;
  }

  void addPolygon() {
    if (polygon_.size() == 3) {
      soup_.triangles.push_back({polygon_[0], polygon_[1], polygon_[2]});
    } else {
      triangulatePolygon(soup_.positions, polygon_, soup_.triangles);
      ++soup_.polygonsTriangulated;
    }
  }

  /// One line, read strictly: the header, the counts, and any vertex or face line the fast path left.
  bool readLine(int64_t line, std::string_view raw) {
    consumed_ += raw.size() + 1;
    tokenize(stripComment(raw), tokens_);
    if (tokens_.count == 0) return true;
    switch (stage_) {
      case Stage::Header: return readHeader(line);
      case Stage::Counts: return handleCounts(line, tokens_.items);
      case Stage::Vertices: return readVertexLine(line);
      case Stage::Faces: return readFaceLine(line, raw);
      case Stage::Done: return fail(parseError(line, "unexpected content after the last face: " + quoted(raw)));
    }
    return true;
  }

  bool readHeader(int64_t line) {
    const auto& items = tokens_.items;
    const std::string_view kw = items[0];
    if (kw != "OFF" && kw != "COFF" && kw != "NOFF")
      return fail(
          Error{ErrorCode::UnsupportedFormat,
                "line " + std::to_string(line) + ": expected the keyword OFF (or COFF, NOFF), found " + quoted(kw)});
    extraPerVertex_ = kw == "COFF" ? 4 : kw == "NOFF" ? 3 : 0;
    stage_ = Stage::Counts;
    if (items.size() > 1) {
      std::vector<std::string_view> rest(items.begin() + 1, items.end());
      return handleCounts(line, rest);
    }
    return true;
  }

  /// OFF: exactly x y z. COFF: x y z and a colour of 3 or 4 values. NOFF: x y z and a normal.
  bool readVertexLine(int64_t line) {
    const auto& items = tokens_.items;
    const size_t count = tokens_.count;
    const bool countOk = extraPerVertex_ == 0   ? count == 3
                         : extraPerVertex_ == 4 ? (count == 6 || count == 7)
                                                : count == 6;
    if (!countOk)
      return fail(parseError(line, "vertex " + std::to_string(soup_.positions.size()) + " has " +
                                       std::to_string(count) + " values, expected " +
                                       (extraPerVertex_ == 0   ? "3 (x y z)"
                                        : extraPerVertex_ == 4 ? "6 or 7 (x y z r g b [a])"
                                                               : "6 (x y z nx ny nz)")));
    double c[3];
    for (int k = 0; k < 3; ++k) {
      const NumberStatus st = parseDouble(items[k], c[k]);
      if (st == NumberStatus::NonFinite)
        return fail(Error{ErrorCode::NonFinite, "line " + std::to_string(line) + ": vertex " +
                                                    std::to_string(soup_.positions.size()) +
                                                    " has a non-finite coordinate " + quoted(items[k])});
      if (st != NumberStatus::Ok)
        return fail(parseError(line, "vertex " + std::to_string(soup_.positions.size()) + ": coordinate " +
                                         quoted(items[k]) + " is not a number"));
    }
    soup_.positions.push_back({c[0], c[1], c[2]});
    if (static_cast<int64_t>(soup_.positions.size()) == nv_) stage_ = nf_ > 0 ? Stage::Faces : Stage::Done;
    return true;
  }

  bool readFaceLine(int64_t line, std::string_view raw) {
    auto& items = tokens_.items;
    const int64_t face = facesRead_;
    int64_t k = 0;
    if (!parseInt64(items[0], k) || k < 0)
      return fail(
          parseError(line, "face " + std::to_string(face) + ": expected a vertex count, found " + quoted(items[0])));
    if (k < 3)
      return fail(Error{ErrorCode::InvalidFace, "line " + std::to_string(line) + ": face " + std::to_string(face) +
                                                    " has " + std::to_string(k) + " vertices (at least 3 needed)"});
    if (static_cast<size_t>(k) + 1 > tokens_.count)
      return fail(parseError(line, "face " + std::to_string(face) + " announces " + std::to_string(k) +
                                       " vertices but lists " + std::to_string(tokens_.count - 1)));
    if (static_cast<size_t>(k) + 1 > items.size()) tokenize(stripComment(raw), tokens_, k + 1 + 4);
    polygon_.clear();
    for (int64_t j = 0; j < k; ++j) {
      int64_t index = 0;
      if (!parseInt64(items[1 + j], index))
        return fail(parseError(line, "face " + std::to_string(face) + ": vertex index " + quoted(items[1 + j]) +
                                         " is not an integer"));
      if (index < 0 || index >= nv_)
        return fail(Error{ErrorCode::IndexOutOfRange,
                          "line " + std::to_string(line) + ": face " + std::to_string(face) + " refers to vertex " +
                              std::to_string(index) + ", but the file has " + std::to_string(nv_) +
                              " vertices (valid: 0.." + std::to_string(nv_ - 1) + ")"});
      polygon_.push_back(static_cast<int32_t>(index));
    }
    // Anything after the indices is a colour: it must be numeric.
    for (size_t j = static_cast<size_t>(k) + 1; j < items.size(); ++j) {
      double ignored;
      if (parseDouble(items[j], ignored) == NumberStatus::NotANumber)
        return fail(parseError(line, "face " + std::to_string(face) + ": unexpected " + quoted(items[j]) +
                                         " after its vertex indices"));
    }
    addPolygon();
    if (++facesRead_ == nf_) stage_ = Stage::Done;
    return true;
  }

  std::string_view text_;
  const BuildLimits& limits_;
  Stage stage_ = Stage::Header;
  PolygonSoup soup_;
  int64_t nv_ = 0, nf_ = 0, facesRead_ = 0;
  size_t extraPerVertex_ = 0;  // COFF: colour (3 or 4 values); NOFF: normal (3)
  std::vector<int32_t> polygon_;
  Tokens tokens_;
  std::optional<Error> error_;
  size_t consumed_ = 0;
};

}  // namespace

Expected<PolygonSoup> readOff(std::string_view text, const BuildLimits& limits) {
  return OffReader(text, limits).read();
}

}  // namespace straightest
