// huge_page_allocator.hpp (private) — a std::allocator for large, short-lived arrays that asks Linux for
// transparent huge pages (2 MiB) where the system leaves them to the program (THP "madvise" mode).
//
// The exact geodesics' propagation fills arrays of a few MiB per call (per halfedge and per edge records)
// and then reads them at random; each 4 KiB page touched first is a page fault, and on a virtual machine
// the faults can cost as much as a small mesh's whole propagation (docs/BENCHMARKS.md). One 2 MiB
// page is one fault (and fewer TLB misses). Allocations below 1 MiB, and other systems, use operator new.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace straightest::detail {

template <typename T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (const size_t bytes = huge(n)) {
      void* p = std::aligned_alloc(kHuge, bytes);
      if (!p) throw std::bad_alloc();
      madvise(p, bytes, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
      return static_cast<T*>(p);
    }
#endif
    if constexpr (alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__)
      return static_cast<T*>(::operator new (n * sizeof(T), std::align_val_t{alignof(T)}));
    else return static_cast<T*>(::operator new(n * sizeof(T)));
  }

  void deallocate(T* p, size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge(n)) {
      std::free(p);
      return;
    }
#else
    (void)n;
#endif
    if constexpr (alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__) ::operator delete (p, std::align_val_t{alignof(T)});
    else ::operator delete(p);
  }

  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
  template <typename U>
  bool operator!=(const HugePageAllocator<U>&) const {
    return false;
  }

 private:
  static constexpr size_t kHuge = size_t{2} << 20;

  /// The bytes to allocate in huge pages for n elements (a multiple of 2 MiB), or 0 for ordinary pages.
  static size_t huge(size_t n) {
    const size_t bytes = n * sizeof(T);
    return bytes < (size_t{1} << 20) ? 0 : (bytes + kHuge - 1) / kHuge * kHuge;
  }
};

/// A std::vector in huge pages when large (HugePageAllocator).
template <typename T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace straightest::detail
