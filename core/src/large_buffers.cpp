// large_buffers.cpp — the huge-page advice for big buffers (large_buffers.hpp).
#include "large_buffers.hpp"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#endif

namespace straightest::detail {

void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && !defined(__EMSCRIPTEN__) && defined(MADV_HUGEPAGE)
  if (data == nullptr || bytes < kLargeBufferBytes) return;
  if (std::getenv("CW_NO_THP")) return;  // TEMPORARY measurement switch
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHugePage - 1);
  // Advice only: where the kernel refuses (no THP, an old kernel) the buffer works as before.
  if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace straightest::detail
