// threads.cpp — the process-wide thread count and parallelFor (threads.hpp, parallel_for.hpp).
// This first version runs every chunk on the calling thread; the thread pool replaces it.
#include <algorithm>
#include <atomic>
#include <thread>

#include "parallel_for.hpp"
#include "straightest/threads.hpp"

namespace straightest {

namespace {
constexpr int kMaxThreads = 64;
std::atomic<int> requestedThreads{0};  // every hardware thread unless set
}  // namespace

int hardwareThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

void setThreadCount(int count) { requestedThreads = std::clamp(count, 0, kMaxThreads); }

int threadCount() {
  const int requested = requestedThreads.load();
  return requested == 0 ? std::min(hardwareThreads(), kMaxThreads) : requested;
}

namespace detail {

bool parallelFor(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t chunk, std::size_t begin, std::size_t end)>& body,
                 const Progress& progress, const char* stage) {
  const std::size_t chunks = chunkCount(count, grain);
  ThrottledProgress report(progress, stage);
  for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
    if (!report(static_cast<double>(chunk) / static_cast<double>(chunks))) return false;
    body(chunk, chunk * grain, std::min(count, (chunk + 1) * grain));
  }
  return chunks == 0 || report(1.0);
}

}  // namespace detail
}  // namespace straightest
