// The OBJ reader (see obj_reader.hpp): one pass over the bytes, one line at a time.
//
// Each `v` and `f` line is first read in place, straight from the bytes, by a fast path that accepts
// only the common, unambiguous form (keyword first, plain decimals, integer indices, nothing after
// them): no line split, no token copies, no allocation per line. Anything else on the line — and
// every error — goes to the strict reading of that one line, which decides exactly what is wrong and
// words the error, so both paths accept the same files and give the same numbers.
//
// Faces may refer to vertices defined later in the file, so an index past the vertices read so far
// is checked once the file ends (its polygon is triangulated then, into triangles reserved in
// place); errors keep the order of a reading that first scans the whole file and then walks its
// faces: any line error, then the vertex cap, then the first face that refers to a missing vertex or
// passes the face cap.
//
// Why our own reader and not tinyobjloader (used until this reader, which had grown in front of it to
// find what it misread, was reading every number anyway): fuzzing found tinyobjloader reading input
// wrongly or with undefined behaviour — exponents of more than 4 digits overflow its arithmetic,
// indices wrap modulo 2³² (atoi), hexadecimal floats read as 0, `0e500` reads as NaN, a `vw` joint
// id overflows an int — its decimals are not correctly rounded, and its errors name no line. Lines
// with an exponent of more than 4 digits are still refused, so that every file accepted before is
// read the same way and every error keeps its message.
#include "obj_reader.hpp"

#include <limits>
#include <optional>

#include "straightest/io/text_scan.hpp"
#include "straightest/mesh/polygon_triangulation.hpp"

namespace straightest {
namespace {

using text::isDigit;
using text::isInlineSpace;
using text::NumberStatus;
using text::parseError;
using text::quoted;

bool isBlank(char c) { return c == ' ' || c == '\t'; }  // what delimits a keyword
bool endsToken(char c) { return isInlineSpace(c) || c == '#'; }

/// True when some number on the line has an exponent of more than 4 digits ("1e-2147483648").
bool longExponent(std::string_view line) {
  for (size_t i = 1; i < line.size(); ++i) {
    if ((line[i] != 'e' && line[i] != 'E') || !(isDigit(line[i - 1]) || line[i - 1] == '.')) continue;
    size_t j = i + 1;
    if (j < line.size() && (line[j] == '+' || line[j] == '-')) ++j;
    size_t digits = 0;
    while (j < line.size() && isDigit(line[j])) ++j, ++digits;
    if (digits > 4) return true;
  }
  return false;
}

/// Longer exponents are refused (see the file comment).
constexpr int kMaxExponentDigits = 4;

/// The common coordinate (text::readDecimalInPlace) with an exponent of at most 4 digits, as the
/// whole token [first, last). Anything else returns false for the strict reading to judge.
bool readCommonCoordinate(const char* first, const char* last, double& out) {
  return text::readDecimalInPlace(first, last, out, kMaxExponentDigits) && first == last;
}

struct DeferredFace {
  int64_t face, line;
  size_t firstTriangle, firstCorner, corners;
};

class ObjReader {
 public:
  ObjReader(std::string_view text, const BuildLimits& limits) : text_(text), limits_(limits) {}

  Expected<PolygonSoup> read() {
    const char* const end = text_.data() + text_.size();
    int64_t line = 0;
    for (const char* p = text_.data(); p < end;) {
      ++line;
      // The common lines, "v x y z" and "f a b c ..." with the keyword first, are read straight from the
      // bytes without finding the line's end first (nearly every line of a large file).
      if (p + 1 < end && p[1] == ' ') {
        const char* next = nullptr;
        if (*p == 'v') {
          next = readVertexInPlace(p + 2, end);
        } else if (*p == 'f' && (next = readFaceInPlace(p + 2, end))) {
          addFace(line);
        }
        if (next) {
          p = next;
          continue;
        }
      }
      const char* e = text_.data() + text::lineEnd(text_, static_cast<size_t>(p - text_.data()));
      const char* keyword = p;
      while (keyword < e && isBlank(*keyword)) ++keyword;
      if (keyword + 1 < e && isBlank(keyword[1]) && (*keyword == 'v' || *keyword == 'f')) {
        const std::string_view raw(p, static_cast<size_t>(e - p));
        const size_t at = static_cast<size_t>(keyword - p);
        std::optional<Error> error;
        if (*keyword == 'v') {
          if (!readCommonVertex(keyword + 2, e)) error = readVertexStrictly(raw, at, line);
        } else {
          if (!readCommonFace(keyword + 2, e)) error = readFaceStrictly(raw, at, line);
          if (!error) addFace(line);
        }
        if (error) return *error;
      }
      p = e == end ? end : e + ((*e == '\r' && e + 1 < end && e[1] == '\n') ? 2 : 1);
    }
    return finish();
  }

 private:
  /// "x y z" and the line's end: the vertex is added and the next line's start returned; nullptr
  /// (nothing added) for anything else, which the line-by-line reading below then judges.
  const char* readVertexInPlace(const char* p, const char* end) {
    double c[3];
    for (double& x : c) {
      p = text::skipInlineSpace(p, end);
      if (!text::readDecimalInPlace(p, end, x, kMaxExponentDigits)) return nullptr;
    }
    const char* next = text::nextLineAt(text::skipInlineSpace(p, end), end);
    if (next) soup_.positions.push_back({c[0], c[1], c[2]});
    return next;
  }

  /// Corners (as readCommonFace reads them) up to the line's end, no comment: polygon_ holds them and
  /// the next line's start is returned; nullptr for anything else.
  const char* readFaceInPlace(const char* p, const char* end) {
    polygon_.clear();
    const int64_t vertices = static_cast<int64_t>(soup_.positions.size());
    for (;;) {
      p = text::skipInlineSpace(p, end);
      if (const char* next = text::nextLineAt(p, end)) return polygon_.size() >= 3 ? next : nullptr;
      const bool negative = *p == '-';
      if (*p == '-' || *p == '+') ++p;
      const char* digits = p;
      int64_t index = 0;
      for (; p < end && isDigit(*p); ++p) {
        if (p - digits == 18) return nullptr;
        index = index * 10 + (*p - '0');
      }
      if (p == digits) return nullptr;
      if (p < end && *p == '/') {
        while (p < end && !endsToken(*p) && *p != '\n' && *p != '\r') ++p;
      }
      if (p < end && !isInlineSpace(*p) && *p != '\n' && *p != '\r') return nullptr;  // a comment, or not an index
      if (negative) index = -index;
      const int64_t resolved = index > 0 ? index - 1 : vertices + index;
      if (index == 0 || resolved < 0 || resolved > std::numeric_limits<int32_t>::max()) return nullptr;
      polygon_.push_back(static_cast<int32_t>(resolved));
    }
  }

  bool readCommonVertex(const char* p, const char* e) {
    double c[3];
    for (double& x : c) {
      while (p < e && isInlineSpace(*p)) ++p;
      const char* token = p;
      while (p < e && !endsToken(*p)) ++p;
      if (!readCommonCoordinate(token, p, x)) return false;
    }
    // What follows (a w, a colour, a comment) is not read, but may not hide a long exponent either.
    if (longExponent(std::string_view(p, static_cast<size_t>(e - p)))) return false;
    soup_.positions.push_back({c[0], c[1], c[2]});
    return true;
  }

  /// Corners as v, v/..., (optional sign, 1..18 digits), resolved to 0-based and in int32 range.
  bool readCommonFace(const char* p, const char* e) {
    polygon_.clear();
    const int64_t vertices = static_cast<int64_t>(soup_.positions.size());
    for (;;) {
      while (p < e && isInlineSpace(*p)) ++p;
      if (p == e || *p == '#') break;
      const bool negative = *p == '-';
      if (*p == '-' || *p == '+') ++p;
      const char* digits = p;
      int64_t index = 0;
      for (; p < e && isDigit(*p); ++p) {
        if (p - digits == 18) return false;
        index = index * 10 + (*p - '0');
      }
      if (p == digits) return false;
      if (p < e && *p == '/') {
        while (p < e && !endsToken(*p)) ++p;
      } else if (p < e && !endsToken(*p)) {
        return false;
      }
      if (negative) index = -index;
      const int64_t resolved = index > 0 ? index - 1 : vertices + index;
      if (index == 0 || resolved < 0 || resolved > std::numeric_limits<int32_t>::max()) return false;
      polygon_.push_back(static_cast<int32_t>(resolved));
    }
    return polygon_.size() >= 3;
  }

  std::optional<Error> readVertexStrictly(std::string_view raw, size_t keyword, int64_t line) {
    if (longExponent(raw)) return parseError(line, "a number has an exponent with more than 4 digits");
    text::tokenize(text::stripComment(raw.substr(keyword + 2)), tokens_, 4);
    // Named as the file counts its vertices (from 1), as the faces' indices are.
    const std::string vertex = std::to_string(soup_.positions.size() + 1) + " (1-based)";
    if (tokens_.count < 3)
      return parseError(line, "vertex " + vertex + " has " + std::to_string(tokens_.count) +
                                  " coordinates, expected at least 3");
    double c[3];
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = tokens_.items[k];
      const NumberStatus status = text::parseDouble(token, c[k]);
      if (status == NumberStatus::NonFinite)
        return Error{ErrorCode::NonFinite, "line " + std::to_string(line) + ": vertex " + vertex +
                                               " has a non-finite coordinate " + quoted(token)};
      if (status != NumberStatus::Ok || !text::isPlainDecimal(token))
        return parseError(line,
                          "vertex " + vertex + ": coordinate " + quoted(token) + " is not a plain decimal number");
    }
    soup_.positions.push_back({c[0], c[1], c[2]});
    return std::nullopt;
  }

  std::optional<Error> readFaceStrictly(std::string_view raw, size_t keyword, int64_t line) {
    const std::string_view corners = text::stripComment(raw.substr(keyword + 2));
    text::tokenize(corners, tokens_, 4);
    if (tokens_.count < 3)
      return Error{ErrorCode::InvalidFace, "line " + std::to_string(line) + ": face " + std::to_string(faces_) +
                                               " has " + std::to_string(tokens_.count) +
                                               " vertices (at least 3 needed)"};
    text::tokenize(corners, tokens_, tokens_.count);
    const int64_t vertices = static_cast<int64_t>(soup_.positions.size());
    polygon_.clear();
    for (std::string_view corner : tokens_.items) {
      int64_t index = 0;
      if (!text::parseInt64(corner.substr(0, corner.find('/')), index))
        return parseError(line, "face " + std::to_string(faces_) + ": vertex index " + quoted(corner) +
                                    " is not an integer (or too large)");
      const int64_t resolved = index > 0 ? index - 1 : vertices + index;
      if (index == 0 || resolved < 0 || resolved > std::numeric_limits<int32_t>::max())
        return Error{ErrorCode::IndexOutOfRange,
                     "line " + std::to_string(line) + ": face " + std::to_string(faces_) + " uses vertex index " +
                         std::to_string(index) +
                         (index == 0 ? " (OBJ indices start at 1)"
                                     : " (" + std::to_string(vertices) + " vertices are defined before this line)")};
      polygon_.push_back(static_cast<int32_t>(resolved));
    }
    return std::nullopt;
  }

  /// Triangulates polygon_ now, or reserves its triangles when it refers to a vertex not read yet.
  void addFace(int64_t line) {
    const int64_t face = faces_++;
    if (polygon_.size() > 3) ++soup_.polygonsTriangulated;
    if (firstFaceOverCap_ >= 0) return;  // the file fails: store no more
    triangles_ += static_cast<int64_t>(polygon_.size()) - 2;
    if (triangles_ > limits_.maxFaces) firstFaceOverCap_ = face;
    const int32_t vertices = static_cast<int32_t>(soup_.positions.size());
    bool forward = false;
    for (int32_t v : polygon_) forward = forward || v >= vertices;
    if (forward) {
      deferred_.push_back({face, line, soup_.triangles.size(), deferredCorners_.size(), polygon_.size()});
      deferredCorners_.insert(deferredCorners_.end(), polygon_.begin(), polygon_.end());
      soup_.triangles.resize(soup_.triangles.size() + polygon_.size() - 2);
    } else if (polygon_.size() == 3) {
      soup_.triangles.push_back({polygon_[0], polygon_[1], polygon_[2]});
    } else {
      triangulatePolygon(soup_.positions, polygon_, soup_.triangles);
    }
  }

  Expected<PolygonSoup> finish() {
    const int64_t nv = static_cast<int64_t>(soup_.positions.size());
    if (nv > limits_.maxVertices)
      return Error{ErrorCode::TooLarge, "file has " + std::to_string(nv) + " vertices, over the limit of " +
                                            std::to_string(limits_.maxVertices)};
    std::vector<Triangle> triangles;
    for (const DeferredFace& d : deferred_) {
      polygon_.assign(deferredCorners_.begin() + static_cast<std::ptrdiff_t>(d.firstCorner),
                      deferredCorners_.begin() + static_cast<std::ptrdiff_t>(d.firstCorner + d.corners));
      for (int32_t index : polygon_)
        if (index >= nv)
          return Error{ErrorCode::IndexOutOfRange,
                       "line " + std::to_string(d.line) + ": face " + std::to_string(d.face) + " refers to vertex " +
                           std::to_string(int64_t{index} + 1) + " (1-based), but the file has " + std::to_string(nv) +
                           " vertices"};
      triangles.clear();
      triangulatePolygon(soup_.positions, polygon_, triangles);
      std::copy(triangles.begin(), triangles.end(),
                soup_.triangles.begin() + static_cast<std::ptrdiff_t>(d.firstTriangle));
    }
    if (firstFaceOverCap_ >= 0)
      return Error{ErrorCode::TooLarge, "file has more than " + std::to_string(limits_.maxFaces) + " faces"};
    if (nv == 0 && soup_.triangles.empty())
      return Error{ErrorCode::UnsupportedFormat, "found neither an OFF header nor OBJ 'v'/'f' lines"};
    return std::move(soup_);
  }

  std::string_view text_;
  BuildLimits limits_;
  PolygonSoup soup_;
  std::vector<int32_t> polygon_;  // the current face's corners, 0-based
  text::Tokens tokens_;
  int64_t faces_ = 0, triangles_ = 0;
  int64_t firstFaceOverCap_ = -1;
  std::vector<DeferredFace> deferred_;
  std::vector<int32_t> deferredCorners_;
};

}  // namespace

Expected<PolygonSoup> readObj(std::string_view text, const BuildLimits& limits) {
  return ObjReader(text, limits).read();
}

}  // namespace straightest
