// memory_warmup.hpp — the CLI's `param` touches the heap the parameterization will take while it reads
// the mesh, on a second thread: on a virtual machine the first touch of memory is what a one-shot run
// pays for most, and reading the mesh leaves a core idle. With the CLI's malloc tunables
// (huge_pages.hpp) freed memory stays with malloc, so the arrays the parameterization allocates next
// take pages that are already backed: a first run then costs about what a repeat does, for a little
// more peak memory (docs/BENCHMARKS.md).
#pragma once
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>

namespace straightest::cli {

/// Below this a warm-up is not worth a thread: malloc serves small blocks from memory already touched.
constexpr std::size_t kMinWarmupBytes = std::size_t{16} << 20;

/// A lower estimate of the heap a measured-boundary parameterization of `mesh` takes, made before the mesh
/// is read (0: none). The call grows the heap by ~315 bytes per vertex (measured on the 1M height field);
/// heightfield:N has N² vertices. An OBJ, OFF or PLY file is taken to hold a vertex per ≤ 300 bytes: the 1M
/// OBJ the CLI writes (texture coordinates included) holds one per 189, the plain 1M OBJ and OFF one
/// per 84 and 82, and binary PLY stores less per vertex than text. So ~1.05 × the file's size stays below
/// what the call takes. Other files (an ASCII STL takes far more bytes per vertex) and the samples get none.
inline std::size_t parameterizationBytes(const std::string& mesh) {
  const std::string field = "heightfield:";
  double bytes = 0;
  if (mesh.compare(0, field.size(), field) == 0) {
    const double n = std::atof(mesh.c_str() + field.size());
    bytes = 315 * n * n;
  } else {
    std::string extension = std::filesystem::path(mesh).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::error_code error;
    const auto size = std::filesystem::file_size(mesh, error);
    if (!error && (extension == ".obj" || extension == ".off" || extension == ".ply"))
      bytes = 1.05 * static_cast<double>(size);
  }
  // At most a quarter of the machine's memory.
  const double physical = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  return static_cast<std::size_t>(std::min(bytes, physical > 0 ? physical / 4 : 0.0));
}

/// Touches `bytes` of heap (none below kMinWarmupBytes) on a second thread from construction to destruction, then
/// gives them back to malloc. The block is allocated on the constructing thread, so it comes from the
/// arena that thread's later allocations use.
class MemoryWarmup {
 public:
  explicit MemoryWarmup(std::size_t bytes)
      : block_(bytes > kMinWarmupBytes ? static_cast<char*>(std::malloc(bytes)) : nullptr) {
    if (!block_) return;
    toucher_ = std::thread([this, bytes] {
      for (std::size_t at = 0; at < bytes; at += 4096) block_[at] = 0;
    });
  }
  ~MemoryWarmup() {
    if (toucher_.joinable()) toucher_.join();
    std::free(block_);
  }
  MemoryWarmup(const MemoryWarmup&) = delete;
  MemoryWarmup& operator=(const MemoryWarmup&) = delete;

 private:
  char* block_;
  std::thread toucher_;
};

}  // namespace straightest::cli
