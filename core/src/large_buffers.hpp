// large_buffers.hpp — how the solver allocates its big arrays: reserved first, asked for transparent
// huge pages (Linux madvise(MADV_HUGEPAGE): the kernel here serves them only on request), then
// filled. A fresh process pays a page fault and a page clearing for every 4 KiB it touches; at a
// million unknowns the solve touches ~1 GB, and 2 MiB pages cut the faults ~500-fold. Elsewhere (and
// in WebAssembly, whose memory is one linear array) the advice is a no-op. Internal to the core.
#pragma once
#include <cstddef>
#include <vector>

namespace straightest::detail {

/// Asks the kernel to back the 2 MiB-aligned part of [data, data + bytes) with huge pages when it is
/// first touched. Below kLargeBufferBytes, or where that is not available, does nothing.
void adviseHugePages(const void* data, std::size_t bytes);

inline constexpr std::size_t kLargeBufferBytes = std::size_t{4} << 20;

/// v = n copies of value in a fresh allocation advised as above before it is touched (v's old
/// contents and storage are dropped; a capacity already large enough is kept as it is).
template <class T>
void assignLarge(std::vector<T>& v, std::size_t n, const T& value) {
  if (v.capacity() < n) {
    std::vector<T>().swap(v);
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
  }
  v.assign(n, value);
}

/// Reserves room for n entries (a fresh allocation advised as above when v must grow).
template <class T>
void reserveLarge(std::vector<T>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  std::vector<T> fresh;
  fresh.reserve(n);
  adviseHugePages(fresh.data(), n * sizeof(T));
  fresh.insert(fresh.end(), v.begin(), v.end());
  v.swap(fresh);
}

}  // namespace straightest::detail
