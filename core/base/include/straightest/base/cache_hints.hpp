// cache_hints.hpp (private) — the two hints the face walks (the cutting-plane tracer and the shooting
// walk) give the compiler about memory and branches, in one place.
#pragma once

namespace straightest::detail {

/// A hint to start loading the cache line of `a` (a no-op where the compiler has no prefetch, as in
/// WebAssembly).
inline void prefetch(const void* a) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(a);
#else
  (void)a;
#endif
}

}  // namespace straightest::detail

// Keeps the branch it stands in: an empty volatile asm statement cannot be executed speculatively, so
// the compiler does not turn the branch into conditional moves. Where a branch is predicted well, a
// conditional move only puts its condition into the chain of dependent loads: Clang did so with the
// tracer's choice of exit (its two arms only assign), which slowed the WASM walk down (GCC keeps the
// branch; computed without it, the native walk was slower too; docs/BENCHMARKS.md).
#if defined(__GNUC__) || defined(__clang__)
#define STRAIGHTEST_KEEP_BRANCH() __asm__ volatile("")
#else
#define STRAIGHTEST_KEEP_BRANCH() ((void)0)
#endif
