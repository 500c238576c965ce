// obj_texcoords.cpp — the uv of every face corner of an OBJ file (`vt` lines, `f v/vt` corners): what a
// program reads back from the atlas or the parameterization's OBJ.
#include <cmath>
#include <optional>
#include <string>

#include "straightest/io/mesh_io.hpp"
#include "straightest/io/text_scan.hpp"

namespace straightest {
namespace {

/// The vt index of one face corner "v/vt[/vn]" (0: none), 1-based as written; negative counts back.
bool cornerTexcoord(std::string_view corner, int64_t& vt) {
  const size_t slash = corner.find('/');
  vt = 0;
  if (slash == std::string_view::npos) return true;
  const std::string_view rest = corner.substr(slash + 1);
  const std::string_view index = rest.substr(0, rest.find('/'));
  return index.empty() || text::parseInt64(index, vt);
}

/// Appends the uv of each corner of face line `tokens` (vt indices resolved against `texcoords`).
Expected<void> readFaceTexcoords(const text::Tokens& tokens, const std::vector<Vec2>& texcoords, int64_t line,
                                 std::vector<Vec2>& cornerUv) {
  if (tokens.count != 4)
    return text::parseError(line,
                            "only triangles carry corner uv here (" + std::to_string(tokens.count - 1) + " corners)");
  for (size_t k = 1; k < 4; ++k) {
    int64_t vt = 0;
    if (!cornerTexcoord(tokens.items[k], vt))
      return text::parseError(line, "bad corner " + text::quoted(tokens.items[k]));
    const int64_t count = static_cast<int64_t>(texcoords.size());
    const int64_t i = vt < 0 ? count + vt : vt - 1;
    if (vt == 0) {
      cornerUv.push_back({std::nan(""), std::nan("")});
    } else if (i < 0 || i >= count) {
      return text::parseError(line, "texture coordinate " + std::to_string(vt) + " does not exist");
    } else {
      cornerUv.push_back(texcoords[i]);
    }
  }
  return {};
}

}  // namespace

Expected<std::vector<Vec2>> readObjCornerUv(std::string_view bytes) {
  std::vector<Vec2> texcoords, cornerUv;
  std::optional<Error> error;
  text::Tokens tokens;
  text::forEachLine(bytes, [&](int64_t line, std::string_view text) {
    text::tokenize(text::stripComment(text), tokens);
    if (tokens.count == 0) return true;
    if (tokens.items[0] == "vt") {
      double u = 0, v = 0;
      if (tokens.count < 3 || text::parseDouble(tokens.items[1], u) != text::NumberStatus::Ok ||
          text::parseDouble(tokens.items[2], v) != text::NumberStatus::Ok)
        error = text::parseError(line, "bad texture coordinate");
      texcoords.push_back({u, v});
    } else if (tokens.items[0] == "f") {
      Expected<void> read = readFaceTexcoords(tokens, texcoords, line, cornerUv);
      if (!read) error = read.error();
    }
    return !error;
  });
  if (error) return *error;
  return cornerUv;
}

}  // namespace straightest
