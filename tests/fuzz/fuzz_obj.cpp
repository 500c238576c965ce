// libFuzzer harness: the OBJ reader (one pass over the bytes + ear clipping + TriMesh::build).
// Invariants (see also fuzz_parse.hpp): an error has a known category and a message, and agrees
// between parsePolygonSoup and loadMesh; a soup never refers to a missing vertex; build's answer
// matches an independent oracle (fuzz_common.hpp); an accepted mesh satisfies every TriMesh
// invariant and survives writing it as OFF and OBJ (with and without uv) and reading it back.
// OBJ only: an accepted file's positions are the numbers written on its `v` lines (read here
// independently with strtod, which rounds correctly like the reader: the same doubles; lines end at
// \n, \r or \r\n, and every coordinate must be a finite number), no face index exceeds the vertex
// count, and every `f` line of k corners gave k − 2 triangles.
#include <cstdlib>
#include <string>

#include "fuzz_parse.hpp"

namespace {

using namespace straightest;

bool isBlank(char c) { return c == ' ' || c == '\t'; }

struct ObjLines {
  std::vector<std::vector<std::string>> vertices, faces;  // tokens after the keyword, comments removed
};

ObjLines readObjLines(std::string_view text) {
  ObjLines out;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = pos;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    std::string_view line = text.substr(pos, end - pos);
    pos = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    size_t i = 0;
    while (i < line.size() && isBlank(line[i])) ++i;
    if (i + 1 >= line.size() || !isBlank(line[i + 1]) || (line[i] != 'v' && line[i] != 'f')) continue;
    std::string_view rest = line.substr(i + 2);
    rest = rest.substr(0, rest.find('#'));
    std::vector<std::string> tokens;
    for (size_t a = 0; a < rest.size();) {
      while (a < rest.size() && (isBlank(rest[a]) || rest[a] == '\v' || rest[a] == '\f')) ++a;
      size_t b = a;
      while (b < rest.size() && !(isBlank(rest[b]) || rest[b] == '\v' || rest[b] == '\f')) ++b;
      if (b > a) tokens.emplace_back(rest.substr(a, b - a));
      a = b;
    }
    (line[i] == 'v' ? out.vertices : out.faces).push_back(std::move(tokens));
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fuzz::checkParse(text, MeshFormat::Obj);

  auto soup = parsePolygonSoup(text, MeshFormat::Obj);
  if (!soup.ok() || soup.value().positions.empty()) return 0;
  const PolygonSoup& s = soup.value();
  const ObjLines lines = readObjLines(text);
  FUZZ_CHECK(lines.vertices.size() == s.positions.size(), "the file has %zu v lines, the soup %zu vertices",
             lines.vertices.size(), s.positions.size());
  for (size_t v = 0; v < lines.vertices.size(); ++v) {
    const auto& tokens = lines.vertices[v];
    FUZZ_CHECK(tokens.size() >= 3, "accepted v line %zu with %zu coordinates", v, tokens.size());
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      const double x = std::strtod(tokens[k].c_str(), &end);
      FUZZ_CHECK(end == tokens[k].c_str() + tokens[k].size() && std::isfinite(x),
                 "accepted v line %zu whose coordinate %d is '%s', not a finite number (read as %.17g)", v, k,
                 tokens[k].c_str(), s.positions[v][k]);
      FUZZ_CHECK(x == s.positions[v][k], "v line %zu coordinate %d is '%s' but was read as %.17g", v, k,
                 tokens[k].c_str(), s.positions[v][k]);
    }
  }
  const long double nv = static_cast<long double>(s.positions.size());
  size_t triangles = 0;
  for (const auto& tokens : lines.faces) {
    triangles += tokens.size() >= 2 ? tokens.size() - 2 : 0;
    for (const std::string& t : tokens) {
      const long double index = std::strtold(t.c_str(), nullptr);  // the vertex part, before any '/'
      FUZZ_CHECK(std::abs(index) >= 1 && std::abs(index) <= nv, "accepted face index '%s' with %zu vertices", t.c_str(),
                 s.positions.size());
    }
  }
  FUZZ_CHECK(triangles == s.triangles.size(), "f lines make %zu triangles, the soup has %zu", triangles,
             s.triangles.size());
  return 0;
}
