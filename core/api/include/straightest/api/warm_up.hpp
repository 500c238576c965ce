// warm_up.hpp — a first call costs more than a repeat: fresh memory is faulted in page by page (slowly on
// a virtual machine; docs/BENCHMARKS.md), and where code is compiled at run time (WebAssembly) the engine
// runs baseline code until it has optimized the hot functions. Loading a mesh is serial and leaves the
// other cores idle; loadWhileWarmingUp uses one of them meanwhile, so that the first parameterization
// after the load runs like a repeat. The warm-up changes no result: it touches memory it gives back, and
// works on a sample of its own.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string_view>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

struct WarmUp {
  std::size_t heapBytes = 0;  // fresh heap to touch and give back to malloc (none when too small to matter)
  // Or the bytes of the mesh file being loaded: the heap for the vertices it holds (verticesInFile, counted
  // on the warm-up's thread). They must stay valid until the load returns.
  std::string_view meshFile;
  MeshFormat format = MeshFormat::Auto;
  bool code = false;  // run the hot loops on a small sample (until once it ran to the end: code stays compiled)
  int64_t maxVertices = std::numeric_limits<int64_t>::max();  // the load's limit: a file's count is capped there
};

/// A lower estimate of the fresh heap a measured-boundary parameterization of a disk with `vertices`
/// vertices takes, in this build (its per-vertex figure was measured on the 1M-vertex height field).
std::size_t parameterizationHeapBytes(int64_t vertices);

/// The vertices a mesh file's bytes hold (Auto: detectMeshFormat), without parsing them: OFF and PLY
/// declare the count in their headers, an OBJ has a `v` line per vertex; 0 for STL (it repeats every
/// corner) and for a header that gives no count. Once *stop is set it gives up (within a megabyte) with 0.
int64_t verticesInFile(std::string_view bytes, MeshFormat format, const std::atomic<bool>* stop = nullptr);

/// Calls load() on the calling thread while a worker of the thread pool does what `warmUp` says. The
/// touched block is allocated on the worker: that serves WebAssembly's single heap; glibc would give it
/// the worker's own arena, which is why the CLI allocates its block on its main thread instead
/// (core/cli/memory_warmup.hpp). The
/// warm-up stops when load returns (within one step of touching or one progress step of the sample), so it
/// never delays the load by more than that. With one thread, or while the pool is taken, only load runs.
void loadWhileWarmingUp(const WarmUp& warmUp, const std::function<void()>& load);

}  // namespace straightest
