// The PLY reader (see ply_reader.hpp): the header becomes a list of elements and their properties, then
// one pass reads every element in order from a value source (ASCII tokens or binary values of either
// byte order), keeping positions and face lists and skipping the rest.
#include "ply_reader.hpp"

#include <cmath>
#include <cstring>
#include <optional>

#include "straightest/io/text_scan.hpp"
#include "straightest/mesh/polygon_triangulation.hpp"

namespace straightest {
namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> typeNamed(std::string_view n) {
  if (n == "char" || n == "int8") return Type::Int8;
  if (n == "uchar" || n == "uint8") return Type::UInt8;
  if (n == "short" || n == "int16") return Type::Int16;
  if (n == "ushort" || n == "uint16") return Type::UInt16;
  if (n == "int" || n == "int32") return Type::Int32;
  if (n == "uint" || n == "uint32") return Type::UInt32;
  if (n == "float" || n == "float32") return Type::Float32;
  if (n == "double" || n == "float64") return Type::Float64;
  return std::nullopt;
}

size_t sizeOf(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8: return 1;
    case Type::Int16:
    case Type::UInt16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

bool isInteger(Type t) { return t != Type::Float32 && t != Type::Float64; }

struct Property {
  std::string name;
  bool isList = false;
  Type countType = Type::UInt8;  // lists only
  Type type = Type::Float32;     // the scalar's type, or a list item's
};

struct Element {
  std::string name;
  int64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct Header {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  size_t dataStart = 0;  // the byte after the end_header line
  int64_t lines = 0;     // header lines (ASCII data line numbers continue from here)
};

Error unsupported(const std::string& what) { return Error{ErrorCode::UnsupportedFormat, what}; }
Error parse(const std::string& what) { return Error{ErrorCode::Parse, what}; }

Expected<Header> readHeader(std::string_view bytes) {
  Header h;
  bool sawFormat = false, ended = false;
  size_t pos = 0;
  text::Tokens tokens;
  while (pos < bytes.size() && !ended) {
    const size_t newline = bytes.find('\n', pos);
    const size_t end = newline == std::string_view::npos ? bytes.size() : newline;
    std::string_view line = bytes.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos = end + 1;
    const int64_t number = ++h.lines;
    const std::string at = "PLY header line " + std::to_string(number) + ": ";
    text::tokenize(line, tokens, 8);
    const auto& t = tokens.items;
    if (number == 1) {
      if (tokens.count != 1 || t[0] != "ply") return unsupported("not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (tokens.count == 0 || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      ended = true;
    } else if (t[0] == "format") {
      if (tokens.count != 3) return parse(at + "expected 'format ENCODING 1.0'");
      if (t[1] == "ascii") h.encoding = Encoding::Ascii;
      else if (t[1] == "binary_little_endian") h.encoding = Encoding::LittleEndian;
      else if (t[1] == "binary_big_endian") h.encoding = Encoding::BigEndian;
      else
        return unsupported(at + "PLY format " + text::quoted(t[1]) +
                           " is not supported (ascii, binary_little_endian or binary_big_endian)");
      if (t[2] != "1.0") return unsupported(at + "PLY version " + text::quoted(t[2]) + " is not supported (1.0)");
      sawFormat = true;
    } else if (t[0] == "element") {
      Element e;
      if (tokens.count != 3 || !text::parseInt64(t[2], e.count) || e.count < 0)
        return parse(at + "expected 'element NAME COUNT' with a count ≥ 0");
      e.name = std::string(t[1]);
      h.elements.push_back(std::move(e));
    } else if (t[0] == "property") {
      if (h.elements.empty()) return parse(at + "a property before any element");
      Property p;
      if (tokens.count >= 2 && t[1] == "list") {
        if (tokens.count != 5) return parse(at + "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
        const auto count = typeNamed(t[2]), item = typeNamed(t[3]);
        if (!count || !item) return parse(at + "unknown type " + text::quoted(count ? t[3] : t[2]));
        if (!isInteger(*count))
          return parse(at + "a list's count type must be an integer type, not " + text::quoted(t[2]));
        p = {std::string(t[4]), true, *count, *item};
      } else {
        if (tokens.count != 3) return parse(at + "expected 'property TYPE NAME'");
        const auto type = typeNamed(t[1]);
        if (!type) return parse(at + "unknown type " + text::quoted(t[1]));
        p = {std::string(t[2]), false, Type::UInt8, *type};
      }
      h.elements.back().properties.push_back(std::move(p));
    } else {
      return parse(at + "unexpected " + text::quoted(t[0]) + " (expected element, property, comment or end_header)");
    }
  }
  if (!ended) return parse("the PLY header has no end_header line (truncated?)");
  if (!sawFormat) return parse("the PLY header has no format line");
  h.dataStart = std::min(pos, bytes.size());
  return h;
}

/// The data section's values one at a time, in the file's encoding; every value comes back as a double
/// (exact for every PLY integer type).
class ValueSource {
 public:
  ValueSource(std::string_view bytes, const Header& h)
      : bytes_(bytes), pos_(h.dataStart), line_(h.lines + 1), encoding_(h.encoding) {}

  /// False at the end of the data, or on a token that is not a number of the type (`error` says which).
  /// `element` and `index` only name the value in an error.
  bool read(Type type, double& out, const std::string& element, int64_t index) {
    if (encoding_ == Encoding::Ascii) return readToken(type, out, element, index);
    const size_t n = sizeOf(type);
    if (bytes_.size() - pos_ < n) {
      error = parse("the file ends inside " + element + " " + std::to_string(index) + " (truncated?)");
      return false;
    }
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    pos_ += n;
    if ((encoding_ == Encoding::BigEndian) == hostIsLittleEndian())
      for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    out = decode(type, b);
    return true;
  }

  size_t remaining() const { return bytes_.size() - pos_; }
  bool ascii() const { return encoding_ == Encoding::Ascii; }
  std::string lineNote() const { return ascii() ? "line " + std::to_string(line_) + ": " : ""; }

  /// After the last element: nothing but (ASCII) whitespace may be left.
  bool atEnd() {
    if (ascii()) skipSpace();
    return pos_ == bytes_.size();
  }

  std::optional<Error> error;

 private:
  static bool hostIsLittleEndian() {
    const uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }

  static double decode(Type type, const unsigned char* b) {
    switch (type) {
      case Type::Int8: return static_cast<double>(static_cast<int8_t>(b[0]));
      case Type::UInt8: return b[0];
      case Type::Int16: return load<int16_t>(b);
      case Type::UInt16: return load<uint16_t>(b);
      case Type::Int32: return load<int32_t>(b);
      case Type::UInt32: return load<uint32_t>(b);
      case Type::Float32: return load<float>(b);
      case Type::Float64: return load<double>(b);
    }
    return 0;
  }
  template <class T>
  static double load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
  }

  void skipSpace() {
    while (pos_ < bytes_.size() && (text::isSpace(bytes_[pos_]) || bytes_[pos_] == '\n')) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  bool readToken(Type type, double& out, const std::string& element, int64_t index) {
    const auto where = [&] { return element + " " + std::to_string(index); };
    skipSpace();
    if (pos_ == bytes_.size()) {
      error = parse("the file ends inside " + where() + " (truncated?)");
      return false;
    }
    size_t end = pos_;
    while (end < bytes_.size() && !text::isSpace(bytes_[end]) && bytes_[end] != '\n') ++end;
    const std::string_view token = bytes_.substr(pos_, end - pos_);
    pos_ = end;
    if (isInteger(type)) {
      int64_t v = 0;
      if (!text::parseInt64(token, v)) {
        error = parse(lineNote() + where() + ": " + text::quoted(token) + " is not an integer");
        return false;
      }
      out = static_cast<double>(v);
      return true;
    }
    const text::NumberStatus status = text::parseDouble(token, out);
    if (status == text::NumberStatus::NonFinite) {
      out = std::nan("");  // the caller reports a non-finite coordinate where it matters
      return true;
    }
    if (status != text::NumberStatus::Ok) {
      error = parse(lineNote() + where() + ": " + text::quoted(token) + " is not a number");
      return false;
    }
    return true;
  }

  std::string_view bytes_;
  size_t pos_;
  int64_t line_;
  Encoding encoding_;
};

int findProperty(const Element& e, std::string_view name) {
  for (size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].name == name) return static_cast<int>(i);
  return -1;
}

/// Which element and properties of the header hold what is read: the vertices' x, y, z and the faces'
/// index list.
struct Layout {
  int vertexElement = -1, faceElement = -1, xyz[3] = {-1, -1, -1}, indexList = -1;
  int64_t vertices = 0, faces = 0;
};

Expected<void> findVertexProperties(const Element& e, Layout& layout) {
  for (int k = 0; k < 3; ++k) {
    const char* axis[] = {"x", "y", "z"};
    layout.xyz[k] = findProperty(e, axis[k]);
    if (layout.xyz[k] < 0) return parse(std::string("the PLY vertex element has no '") + axis[k] + "' property");
    if (e.properties[layout.xyz[k]].isList)
      return parse(std::string("the PLY vertex property '") + axis[k] + "' is a list");
  }
  return {};
}

Expected<void> findFaceIndices(const Element& e, Layout& layout) {
  layout.indexList = findProperty(e, "vertex_indices");
  if (layout.indexList < 0) layout.indexList = findProperty(e, "vertex_index");
  if (layout.indexList < 0 || !e.properties[layout.indexList].isList)
    return parse("the PLY face element has no list property 'vertex_indices' (or 'vertex_index')");
  if (!isInteger(e.properties[layout.indexList].type))
    return unsupported("the PLY face list 'vertex_indices' has a floating-point item type; indices must be integers");
  return {};
}

Expected<Layout> findLayout(const Header& h, const BuildLimits& limits) {
  Layout layout;
  for (size_t i = 0; i < h.elements.size(); ++i) {
    const Element& e = h.elements[i];
    Expected<void> found;
    if (e.name == "vertex" && layout.vertexElement < 0) {
      layout.vertexElement = static_cast<int>(i);
      found = findVertexProperties(e, layout);
    } else if (e.name == "face" && layout.faceElement < 0) {
      layout.faceElement = static_cast<int>(i);
      found = findFaceIndices(e, layout);
    }
    if (!found) return found.error();
  }
  if (layout.vertexElement < 0) return parse("the PLY header has no 'vertex' element");
  if (layout.faceElement < 0)
    return Error{ErrorCode::Empty, "the PLY file has no 'face' element (a point cloud?): there is no surface to read"};
  const int64_t nv = h.elements[layout.vertexElement].count, nf = h.elements[layout.faceElement].count;
  if (nv > limits.maxVertices || nf > limits.maxFaces)
    return Error{ErrorCode::TooLarge, "the PLY header claims " + std::to_string(nv) + " vertices and " +
                                          std::to_string(nf) + " faces, over the limits of " +
                                          std::to_string(limits.maxVertices) + " vertices and " +
                                          std::to_string(limits.maxFaces) + " faces"};
  layout.vertices = nv;
  layout.faces = nf;
  return layout;
}

/// What the elements' bodies hold: the vertices, and every face's indices one after another.
struct Body {
  PolygonSoup soup;
  std::vector<int32_t> corners;
  std::vector<int64_t> firstCorner{0};  // face f: corners[firstCorner[f] .. firstCorner[f + 1])
};

/// Before allocating: every instance takes at least this many bytes (binary: its scalars and list
/// counts; ASCII: a character and a separator per value, the very last value needing no separator).
Expected<void> checkElementFits(const Element& e, const ValueSource& source) {
  uint64_t least = 0;
  for (const Property& p : e.properties) least += source.ascii() ? 2 : sizeOf(p.isList ? p.countType : p.type);
  if (static_cast<uint64_t>(e.count) > (source.remaining() + 1) / least)
    return parse("the PLY header claims " + std::to_string(e.count) + " '" + e.name + "' elements, but only " +
                 std::to_string(source.remaining()) + " bytes follow (the file is truncated or the header lies)");
  return {};
}

/// One list property of instance i, whose count has been read; its items are kept only if they are the
/// faces' indices.
Expected<void> readList(ValueSource& source, const Element& e, const Property& p, int64_t i, double count, bool indices,
                        int64_t vertices, std::vector<int32_t>& corners) {
  const double itemBytes = source.ascii() ? 2.0 : static_cast<double>(sizeOf(p.type));
  if (count < 0 || count * itemBytes > static_cast<double>(source.remaining()))
    return parse(source.lineNote() + e.name + " " + std::to_string(i) + ": a list of " +
                 std::to_string(static_cast<int64_t>(count)) + " values does not fit in the " +
                 std::to_string(source.remaining()) + " bytes left (truncated?)");
  const int64_t k = static_cast<int64_t>(count);
  if (indices && k < 3)
    return Error{ErrorCode::InvalidFace, source.lineNote() + "face " + std::to_string(i) + " has " + std::to_string(k) +
                                             " vertices (at least 3 needed)"};
  for (int64_t j = 0; j < k; ++j) {
    double item = 0;
    if (!source.read(p.type, item, e.name, i)) return *source.error;
    if (!indices) continue;
    if (item < 0 || item >= static_cast<double>(vertices))
      return Error{ErrorCode::IndexOutOfRange, source.lineNote() + "face " + std::to_string(i) + " refers to vertex " +
                                                   std::to_string(static_cast<int64_t>(item)) + ", but the file has " +
                                                   std::to_string(vertices) + " vertices"};
    corners.push_back(static_cast<int32_t>(item));
  }
  return {};
}

/// Every instance of element ei, keeping the vertices' coordinates and the faces' indices.
Expected<void> readElement(ValueSource& source, const Header& h, size_t ei, const Layout& layout, Body& body) {
  const Element& e = h.elements[ei];
  if (auto fits = checkElementFits(e, source); !fits) return fits.error();
  const bool isVertex = static_cast<int>(ei) == layout.vertexElement,
             isFace = static_cast<int>(ei) == layout.faceElement;
  if (isVertex) body.soup.positions.reserve(e.count);
  if (isFace) body.firstCorner.reserve(e.count + 1);
  for (int64_t i = 0; i < e.count; ++i) {
    double c[3] = {0, 0, 0};
    for (size_t pi = 0; pi < e.properties.size(); ++pi) {
      const Property& p = e.properties[pi];
      double value = 0;
      if (!source.read(p.isList ? p.countType : p.type, value, e.name, i)) return *source.error;
      if (p.isList) {
        const bool indices = isFace && static_cast<int>(pi) == layout.indexList;
        if (auto read = readList(source, e, p, i, value, indices, layout.vertices, body.corners); !read)
          return read.error();
      } else {
        for (int k = 0; k < 3; ++k)
          if (isVertex && layout.xyz[k] == static_cast<int>(pi)) c[k] = value;
      }
    }
    if (isVertex) {
      if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
        return Error{ErrorCode::NonFinite,
                     source.lineNote() + "vertex " + std::to_string(i) + " has a non-finite coordinate"};
      body.soup.positions.push_back({c[0], c[1], c[2]});
    }
    if (isFace) body.firstCorner.push_back(static_cast<int64_t>(body.corners.size()));
  }
  return {};
}

/// The faces as triangles: triangles as they are, larger polygons triangulated.
void triangulateFaces(Body& body, int64_t faces) {
  PolygonSoup& soup = body.soup;
  std::vector<int32_t> polygon;
  soup.triangles.reserve(static_cast<size_t>(faces));
  for (size_t f = 0; f + 1 < body.firstCorner.size(); ++f) {
    polygon.assign(body.corners.begin() + body.firstCorner[f], body.corners.begin() + body.firstCorner[f + 1]);
    if (polygon.size() == 3) {
      soup.triangles.push_back({polygon[0], polygon[1], polygon[2]});
    } else {
      triangulatePolygon(soup.positions, polygon, soup.triangles);
      ++soup.polygonsTriangulated;
    }
  }
}

}  // namespace

bool looksLikePly(std::string_view bytes) {
  return bytes.size() >= 4 && bytes.substr(0, 3) == "ply" && (bytes[3] == '\n' || bytes[3] == '\r');
}

Expected<PolygonSoup> readPly(std::string_view bytes, const BuildLimits& limits) {
  auto header = readHeader(bytes);
  if (!header) return header.error();
  const Header& h = header.value();
  auto layout = findLayout(h, limits);
  if (!layout) return layout.error();
  Body body;
  ValueSource source(bytes, h);
  for (size_t ei = 0; ei < h.elements.size(); ++ei) {
    const Element& e = h.elements[ei];
    if (e.properties.empty() || e.count == 0) continue;
    if (auto read = readElement(source, h, ei, layout.value(), body); !read) return read.error();
  }
  if (!source.atEnd())
    return parse(source.lineNote() + std::to_string(source.remaining()) +
                 " bytes follow the last PLY element (the header's counts are too small?)");
  triangulateFaces(body, layout.value().faces);
  return std::move(body.soup);
}

}  // namespace straightest
