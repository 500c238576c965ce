// The machine's memory bandwidth, STREAM-style: the triad a = b + s·c over three 128 MB arrays, on 1 and
// 2 threads (best of 5 each, in turn twice). Why: to tell a stage bound by memory traffic (it would run
// near these rates) from one bound by latency (dependent loads, a loop-carried chain) — the solver's
// V-cycle reads a few hundred MB per cycle at 1M vertices. Native only; never pass/fail.
//   bench_bandwidth
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

int main() {
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
  return a[n / 2] == 3.5 ? 0 : 1;  // uses the result
}
