// The machine's memory bandwidth, STREAM-style: the triad a = b + s·c over three 128 MB arrays, on 1 and
// 2 threads (best of 5 each, in turn twice). Why: to tell a stage bound by memory traffic (it would run
// near these rates) from one bound by latency (dependent loads, a loop-carried chain) — the solver's
// V-cycle reads a few hundred MB per cycle at 1M vertices. Then the cost of first-touching fresh memory
// (a new mapping, huge pages advised, zeroed by one thread), which is what a cold call pays for every
// buffer it allocates: on a virtual machine it depends on whether the host still backs the pages (run it
// twice in a row, then again after the machine has been idle for a minute). Native only; never pass/fail.
//   bench_bandwidth [FIRST_TOUCH_MB]
#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
  const size_t n = size_t{16} << 20;  // 16M doubles: 128 MB per array
  std::vector<double> a(n, 1), b(n, 2), c(n, 3);
  for (int threads : {1, 2, 1, 2}) {
    double best = 1e30;
    for (int repeat = 0; repeat < 5; ++repeat) {
      const auto start = std::chrono::steady_clock::now();
      std::vector<std::thread> pool;
      for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
          const size_t lo = n * t / threads, hi = n * (t + 1) / threads;
          for (size_t i = lo; i < hi; ++i) a[i] = b[i] + 0.5 * c[i];
        });
      for (std::thread& thread : pool) thread.join();
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("threads %d: triad %.1f GB/s (best of 5 over 3 x 128 MB)\n", threads,
                3.0 * n * sizeof(double) / best / 1e9);
  }
  const size_t touchMB = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 512;
  const size_t bytes = touchMB << 20;
  void* fresh = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (fresh == MAP_FAILED) return 1;
  madvise(fresh, bytes, MADV_HUGEPAGE);
  const auto start = std::chrono::steady_clock::now();
  std::memset(fresh, 0, bytes);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("first touch of %zu MB (fresh mapping, huge pages advised, one thread): %.0f ms, %.2f ms per MB\n",
              touchMB, ms, ms / touchMB);
  munmap(fresh, bytes);
  return a[n / 2] == 3.5 ? 0 : 1;  // uses the result
}
