// The warm-up of warm_up.hpp: a heap block touched page by page, and the measured-boundary
// parameterization and boundary traces of a small height field, on a pool worker while the caller loads.
#include "straightest/api/warm_up.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>

#if defined(__EMSCRIPTEN__)
#include <emscripten/heap.h>
#endif

#include "straightest/base/parallel_for.hpp"
#include "straightest/io/text_scan.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"

namespace straightest {
namespace {

constexpr std::size_t kMinHeapBytes = std::size_t{16} << 20;  // below this a first touch costs little
constexpr std::size_t kTouchStep = std::size_t{1} << 20;      // how much is touched between looks at stop
constexpr std::size_t kPageBytes = 4096;

/// Touches `bytes` of fresh heap until stop, then gives it back. Freed, the block stays with malloc
/// (glibc under the CLI's tunables; WebAssembly memory never shrinks), so the next large allocations take
/// pages that are already backed.
void touchHeap(std::size_t bytes, const std::atomic<bool>& stop) {
  const std::unique_ptr<char, decltype(&std::free)> block(static_cast<char*>(std::malloc(bytes)), &std::free);
  if (!block) return;
  volatile char* at = block.get();
  for (std::size_t done = 0; done < bytes && !stop.load(std::memory_order_relaxed); done += kTouchStep)
    for (std::size_t page = done; page < std::min(bytes, done + kTouchStep); page += kPageBytes) at[page] = 0;
}

/// The hot loops (traces, weights, the multigrid solve, the metrics) on a 100 × 100 height field, three
/// times: where code is compiled at run time this gets the hot functions optimized. Every stage checks
/// stop through its progress; whether all three rounds ran.
bool exerciseHotLoops(const std::atomic<bool>& stop) {
  const TriMesh sample = makeHeightField(100);
  const Progress untilStopped = [&](const char*, double) { return !stop.load(std::memory_order_relaxed); };
  for (int round = 0; round < 3; ++round)
    if (!parameterize(sample, ParamOptions{}, untilStopped)) return false;
  return true;
}

/// A token's value as a count: digits only, else 0.
int64_t wholeNumber(std::string_view token) {
  int64_t value = 0;
  for (char c : token) {
    if (!text::isDigit(c) || value > (int64_t{1} << 40)) return 0;
    value = 10 * value + (c - '0');
  }
  return value;
}

/// How far the heap can still grow: in WebAssembly up to the module's maximum memory; natively no bound
/// is known (an allocation that cannot be served fails, and then nothing is touched).
std::size_t heapHeadroom() {
#if defined(__EMSCRIPTEN__)
  return emscripten_get_heap_max() - emscripten_get_heap_size();
#else
  return std::numeric_limits<std::size_t>::max();
#endif
}

std::atomic<bool> codeWarmed{false};  // the sample ran to the end once (one warm-up at a time: the pool)

}  // namespace

std::size_t parameterizationHeapBytes(int64_t vertices) {
  // Fresh heap the first call takes, per vertex, as measured at 1M vertices (natively the heap's growth
  // by mallinfo2; in WebAssembly, with 32-bit pointers, the module memory's growth): docs/BENCHMARKS.md.
#if defined(__wasm__)
  constexpr double kBytesPerVertex = 250;
#else
  constexpr double kBytesPerVertex = 310;
#endif
  if (vertices <= 0) return 0;
  const double bytes = kBytesPerVertex * static_cast<double>(vertices);
  constexpr auto kMost = std::numeric_limits<std::size_t>::max();
  return bytes >= static_cast<double>(kMost) ? kMost : static_cast<std::size_t>(bytes);  // 32-bit size_t: saturate
}

int64_t verticesInFile(std::string_view bytes, MeshFormat format, const std::atomic<bool>* stop) {
  if (format == MeshFormat::Auto) format = detectMeshFormat(bytes);
  auto stopped = [&] { return stop && stop->load(std::memory_order_relaxed); };
  int64_t count = 0;
  if (format == MeshFormat::Obj) {
    for (size_t at = 0, look = 0; at < bytes.size();) {
      if (at >= look) {  // a look at stop every megabyte: a failed load must not wait for the count
        if (stopped()) return 0;
        look = at + kTouchStep;
      }
      const char* p = text::skipInlineSpace(bytes.data() + at, bytes.data() + bytes.size());
      const char* end = bytes.data() + bytes.size();
      if (end - p >= 2 && p[0] == 'v' && text::isInlineSpace(p[1])) ++count;
      const void* newline = std::memchr(p, '\n', static_cast<size_t>(end - p));
      at = newline ? static_cast<size_t>(static_cast<const char*>(newline) - bytes.data()) + 1 : bytes.size();
    }
    return count;
  }
  // OFF: the first number after the keyword; PLY: "element vertex N" before end_header.
  bool keyword = false;
  text::forEachLine(bytes, [&](int64_t lineNumber, std::string_view line) {
    if (lineNumber % 4096 == 0 && stopped()) return false;  // a PLY header without end_header: whole file
    text::Tokens t;
    text::tokenize(text::stripComment(line), t, 3);
    const size_t n = std::min<size_t>(t.count, 3);
    if (format == MeshFormat::Ply) {
      if (n >= 1 && t.items[0] == "end_header") return false;
      if (n == 3 && t.items[0] == "element" && t.items[1] == "vertex") count = wholeNumber(t.items[2]);
      return count == 0;
    }
    if (format != MeshFormat::Off) return false;
    for (size_t i = 0; i < n; ++i) {
      if (!keyword) {
        keyword = true;
        continue;
      }
      count = wholeNumber(t.items[i]);
      return false;
    }
    return true;
  });
  return stopped() ? 0 : count;
}

void loadWhileWarmingUp(const WarmUp& warmUp, const std::function<void()>& load) {
  const bool file = !warmUp.meshFile.empty();
  const bool code = warmUp.code && !codeWarmed.load();
  if (!file && warmUp.heapBytes < kMinHeapBytes && !code) return load();
  detail::runAlongside(
      [&](const std::atomic<bool>& stop) {
        // Code first: a sample round takes tens of milliseconds, and until the hot functions are
        // optimized every loop of the real call runs slower.
        if (code && exerciseHotLoops(stop)) codeWarmed = true;
        if (stop) return;
        std::size_t heap = warmUp.heapBytes;
        if (file) {
          // A header can claim any count: no more vertices than the limit and than the bytes can hold
          // (3 per vertex at the least: binary PLY with one-byte coordinates).
          const int64_t claimed = verticesInFile(warmUp.meshFile, warmUp.format, &stop);
          heap = parameterizationHeapBytes(
              std::min({claimed, warmUp.maxVertices, static_cast<int64_t>(warmUp.meshFile.size() / 3)}));
        }
        heap = std::min(heap, heapHeadroom() / 2);  // never what would make the load run out of memory
        if (heap >= kMinHeapBytes && !stop) touchHeap(heap, stop);
      },
      load);
}

}  // namespace straightest
