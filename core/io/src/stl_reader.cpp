// The STL reader (see stl_reader.hpp): both encodings hand corners to one welder, which numbers each
// distinct point once and drops the triangles welding collapses.
#include "stl_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <unordered_map>

#include "straightest/io/text_scan.hpp"

namespace straightest {
namespace {

/// Corners to shared vertices by exact equality of the three doubles.
class Welder {
 public:
  explicit Welder(PolygonSoup& soup) : soup_(soup) {}

  void reserve(size_t triangles) {
    index_.reserve(triangles / 2 + 3);
    soup_.triangles.reserve(triangles);
  }

  void addTriangle(const Vec3 (&corners)[3]) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t[k] = vertexOf(corners[k]);
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) ++collapsed_;
    else soup_.triangles.push_back(t);
  }

  int64_t collapsed() const { return collapsed_; }

 private:
  struct Key {
    uint64_t x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
      h = (h ^ (h >> 31) ^ k.y) * 0xBF58476D1CE4E5B9ull;
      return static_cast<size_t>((h ^ (h >> 29) ^ k.z) * 0x94D049BB133111EBull);
    }
  };
  static uint64_t bits(double d) {
    if (d == 0) d = 0;  // −0 and +0 are one point
    uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
  }
  int32_t vertexOf(const Vec3& p) {
    const auto [it, added] = index_.emplace(Key{bits(p.x), bits(p.y), bits(p.z)},
                                            static_cast<int32_t>(soup_.positions.size()));
    if (added) soup_.positions.push_back(p);
    return it->second;
  }

  PolygonSoup& soup_;
  std::unordered_map<Key, int32_t, KeyHash> index_;
  int64_t collapsed_ = 0;
};

uint32_t littleEndian32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

float littleEndianFloat(const char* p) {
  const uint32_t bits = littleEndian32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

/// Dropped triangles become a note, or the error when nothing is left.
std::optional<Error> noteCollapsed(PolygonSoup& soup, const Welder& welder) {
  if (welder.collapsed() > 0 && soup.triangles.empty())
    return Error{ErrorCode::Degenerate, "every STL triangle (" + std::to_string(welder.collapsed()) +
                                            ") has two equal corners: there is no surface"};
  if (welder.collapsed() > 0)
    soup.notes.push_back(std::to_string(welder.collapsed()) +
                         " STL triangles with two equal corners were dropped (zero area after welding)");
  return std::nullopt;
}

Expected<PolygonSoup> readBinaryStl(std::string_view bytes, const BuildLimits& limits) {
  if (bytes.size() < 84)
    return Error{ErrorCode::Parse,
                 "a binary STL needs at least 84 bytes (an 80-byte header and a triangle count), "
                 "the file has " +
                     std::to_string(bytes.size())};
  const uint64_t count = littleEndian32(bytes.data() + 80);
  if (count > static_cast<uint64_t>(limits.maxFaces))
    return Error{ErrorCode::TooLarge, "the binary STL header claims " + std::to_string(count) +
                                          " triangles, over the limit of " + std::to_string(limits.maxFaces)};
  const uint64_t needed = 84 + 50 * count;
  if (needed > bytes.size())
    return Error{ErrorCode::Parse, "the binary STL header claims " + std::to_string(count) + " triangles (" +
                                       std::to_string(needed) + " bytes), but the file has " +
                                       std::to_string(bytes.size()) + " bytes (truncated?)"};
  PolygonSoup soup;
  Welder welder(soup);
  welder.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    const char* record = bytes.data() + 84 + 50 * i + 12;  // after the facet normal
    Vec3 corners[3];
    for (int k = 0; k < 3; ++k) {
      const double c[3] = {littleEndianFloat(record + 12 * k), littleEndianFloat(record + 12 * k + 4),
                           littleEndianFloat(record + 12 * k + 8)};
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        return Error{ErrorCode::NonFinite, "triangle " + std::to_string(i) + " has a non-finite coordinate"};
      corners[k] = {c[0], c[1], c[2]};
    }
    welder.addTriangle(corners);
    if (static_cast<int64_t>(soup.positions.size()) > limits.maxVertices)
      return Error{ErrorCode::TooLarge, "more than " + std::to_string(limits.maxVertices) + " distinct vertices"};
  }
  if (needed < bytes.size())
    soup.notes.push_back(std::to_string(bytes.size() - needed) + " bytes after the last STL triangle were ignored");
  if (auto error = noteCollapsed(soup, welder)) return *error;
  return soup;
}

/// Whitespace-separated words of the text, with their line numbers.
class Words {
 public:
  explicit Words(std::string_view text) : text_(text) {}
  /// The next word, or an empty view at the end.
  std::string_view next() {
    while (pos_ < text_.size() && (text::isSpace(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && !text::isSpace(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  void skipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
  }
  int64_t line() const { return line_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int64_t line_ = 1;
};

Expected<PolygonSoup> readAsciiStl(std::string_view bytes, const BuildLimits& limits) {
  PolygonSoup soup;
  Welder welder(soup);
  Words words(bytes);
  int64_t facets = 0;
  const auto expected = [&](const char* what, std::string_view found) {
    return text::parseError(words.line(),
                            "expected " + std::string(what) + ", found " +
                                (found.empty() ? std::string("the end of the file") : text::quoted(found)));
  };
  const auto expect = [&](const char* keyword) -> std::optional<Error> {
    const std::string_view w = words.next();
    if (w == keyword) return std::nullopt;
    return expected((std::string("'") + keyword + "'").c_str(), w);
  };
  std::string_view word = words.next();
  if (word != "solid") return expected("'solid'", word);
  words.skipLine();  // the solid's name
  while (true) {
    word = words.next();
    if (word == "endsolid") {
      words.skipLine();
      word = words.next();
      if (word.empty()) break;
      if (word != "solid") return expected("'solid' or the end of the file", word);
      words.skipLine();
      continue;
    }
    if (word != "facet") return expected("'facet' or 'endsolid'", word);
    if (++facets > limits.maxFaces)
      return Error{ErrorCode::TooLarge, "more than " + std::to_string(limits.maxFaces) + " STL facets"};
    if (auto e = expect("normal")) return *e;
    for (int k = 0; k < 3; ++k) words.next();  // the normal: recomputed from the corners, never read
    if (auto e = expect("outer")) return *e;
    if (auto e = expect("loop")) return *e;
    Vec3 corners[3];
    for (int k = 0; k < 3; ++k) {
      if (auto e = expect("vertex")) return *e;
      double c[3];
      for (double& x : c) {
        const std::string_view token = words.next();
        const text::NumberStatus status = text::parseDouble(token, x);
        if (status == text::NumberStatus::NonFinite)
          return Error{ErrorCode::NonFinite, "line " + std::to_string(words.line()) + ": facet " +
                                                 std::to_string(facets - 1) + " has a non-finite coordinate " +
                                                 text::quoted(token)};
        if (status != text::NumberStatus::Ok) return expected("a coordinate", token);
      }
      corners[k] = {c[0], c[1], c[2]};
    }
    word = words.next();
    if (word == "vertex")
      return Error{ErrorCode::InvalidFace, "line " + std::to_string(words.line()) + ": facet " +
                                               std::to_string(facets - 1) + " has more than 3 vertices"};
    if (word != "endloop") return expected("'endloop'", word);
    if (auto e = expect("endfacet")) return *e;
    welder.addTriangle(corners);
    if (static_cast<int64_t>(soup.positions.size()) > limits.maxVertices)
      return Error{ErrorCode::TooLarge, "more than " + std::to_string(limits.maxVertices) + " distinct vertices"};
  }
  if (auto error = noteCollapsed(soup, welder)) return *error;
  return soup;
}

}  // namespace

bool looksLikeBinaryStl(std::string_view bytes) {
  return bytes.size() >= 84 && 84 + 50 * static_cast<uint64_t>(littleEndian32(bytes.data() + 80)) == bytes.size();
}

bool looksLikeAsciiStl(std::string_view bytes) {
  size_t i = 0;
  while (i < bytes.size() && (text::isSpace(bytes[i]) || bytes[i] == '\n')) ++i;
  if (bytes.substr(i, 5) != "solid" || (i + 5 < bytes.size() && !text::isSpace(bytes[i + 5]) && bytes[i + 5] != '\n'))
    return false;
  return std::memchr(bytes.data(), 0, std::min<size_t>(bytes.size(), 4096)) == nullptr;
}

Expected<PolygonSoup> readStl(std::string_view bytes, const BuildLimits& limits) {
  if (bytes.empty()) return Error{ErrorCode::Empty, "file is empty"};
  return looksLikeAsciiStl(bytes) && !looksLikeBinaryStl(bytes) ? readAsciiStl(bytes, limits)
                                                                : readBinaryStl(bytes, limits);
}

}  // namespace straightest
