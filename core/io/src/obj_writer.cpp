// The OBJ writer (declared in mesh_io.hpp): a mesh, and optionally one texture coordinate per vertex,
// as OBJ text. Each coordinate is written with the fewest significant digits (15, 16 or 17) that read
// back as exactly the same double (`0.3346`, not `0.33460000000000001`): the shortest that round-trips
// whenever it has 15 digits or fewer (any decimal of ≤ 15 digits survives a trip through a double), else
// the closest 16- or 17-digit one. (std::to_chars for double would do it, but Emscripten 3.1.6's libc++
// lacks it.) vertices keep the mesh's order, so `vt` k belongs to vertex k. With a uv per
// face corner (a cut mesh's map) each distinct uv is one `vt`, in the order faces first use it.
// Formatting is the writer's whole cost (up to three snprintf per number),
// so runs of lines are formatted on all threads into their own strings and appended in order: the text
// is the same for any thread count.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <unordered_map>

#include <fast_float/fast_float.h>

#include "straightest/base/parallel_for.hpp"
#include "straightest/io/mesh_io.hpp"

namespace straightest {
namespace {

/// The shortest of %.15g, %.16g, %.17g that reads back as x (the last always does). Read back with
/// fast_float, correctly rounded as strtod is, so the same choice.
void appendNumber(std::string& out, double x) {
  char text[40];
  for (int digits = 15; digits <= 17; ++digits) {
    const int length = std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (digits == 17 || !std::isfinite(x)) break;
    double back = 0;
    const auto read = fast_float::from_chars(text, text + length, back);
    if (read.ec == std::errc() && back == x) break;
  }
  out += text;
}

void appendLine(std::string& out, const char* keyword, std::initializer_list<double> values) {
  out += keyword;
  for (double v : values) {
    out += ' ';
    appendNumber(out, v);
  }
  out += '\n';
}

/// line(out, i) for i in [0, count), in order; runs of lines formatted on all threads.
template <class Line>
void appendLines(std::string& out, size_t count, const Line& line) {
  constexpr size_t kLinesPerRun = 16384;
  std::vector<std::string> runs(detail::chunkCount(count, kLinesPerRun));
  detail::parallelFor(count, kLinesPerRun, [&](size_t run, size_t begin, size_t end) {
    std::string& text = runs[run];
    text.reserve((end - begin) * 48);
    for (size_t i = begin; i < end; ++i) line(text, i);
  });
  size_t total = out.size();
  for (const std::string& text : runs) total += text.size();
  out.reserve(total);
  for (std::string& text : runs) {
    out += text;
    std::string().swap(text);
  }
}

void appendFace(std::string& out, const Triangle& t, const int32_t* vt) {
  char line[160];
  if (vt) std::snprintf(line, sizeof line, "f %d/%d %d/%d %d/%d\n", t[0] + 1, vt[0], t[1] + 1, vt[1], t[2] + 1, vt[2]);
  else std::snprintf(line, sizeof line, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
  out += line;
}

void appendPositions(std::string& out, const TriMesh& mesh) {
  const std::vector<Vec3>& positions = mesh.positions();
  appendLines(out, positions.size(), [&](std::string& text, size_t i) {
    appendLine(text, "v", {positions[i].x, positions[i].y, positions[i].z});
  });
}

}  // namespace

std::string writeObj(const TriMesh& mesh, const std::vector<Vec2>* uv) {
  std::string out = "# written by straightest\n";
  appendPositions(out, mesh);
  if (uv)
    appendLines(out, uv->size(), [&](std::string& text, size_t i) {
      appendLine(text, "vt", {(*uv)[i].x, (*uv)[i].y});
    });
  appendLines(out, static_cast<size_t>(mesh.numFaces()), [&](std::string& text, size_t f) {
    const Triangle& t = mesh.triangle(static_cast<int32_t>(f));
    const int32_t vt[3] = {t[0] + 1, t[1] + 1, t[2] + 1};
    appendFace(text, t, uv ? vt : nullptr);
  });
  return out;
}

std::string writeObjWithCornerUv(const TriMesh& mesh, const std::vector<Vec2>& cornerUv) {
  std::string out = "# written by straightest (a vt per distinct corner uv: seams split)\n";
  appendPositions(out, mesh);
  // Distinct by exact value (bit pattern, with +0 and −0 as one): the copies of a vertex on one side of
  // a seam carry the very same doubles, the two sides different ones.
  struct Key {
    uint64_t x, y;
    bool operator==(const Key& o) const { return x == o.x && y == o.y; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const { return std::hash<uint64_t>()(k.x * 0x9E3779B97F4A7C15ull ^ k.y); }
  };
  const auto bits = [](double d) {
    if (d == 0) d = 0;  // −0 → +0
    uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
  };
  const size_t nf = static_cast<size_t>(mesh.numFaces());
  const bool usable = cornerUv.size() == 3 * nf;
  std::unordered_map<Key, int32_t, KeyHash> index;
  std::vector<int32_t> vt(3 * nf, 0);  // 1-based vt per corner; 0: the face is written without vt
  for (size_t f = 0; usable && f < nf; ++f) {
    bool finite = true;
    for (int k = 0; k < 3; ++k) finite = finite && isFinite(cornerUv[3 * f + k]);
    if (!finite) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec2& t = cornerUv[3 * f + k];
      const auto [it, added] = index.emplace(Key{bits(t.x), bits(t.y)}, static_cast<int32_t>(index.size()) + 1);
      if (added) appendLine(out, "vt", {t.x, t.y});
      vt[3 * f + k] = it->second;
    }
  }
  appendLines(out, nf, [&](std::string& text, size_t f) {
    appendFace(text, mesh.triangle(static_cast<int32_t>(f)), vt[3 * f] > 0 ? &vt[3 * f] : nullptr);
  });
  return out;
}

}  // namespace straightest
