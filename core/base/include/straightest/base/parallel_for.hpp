// parallel_for.hpp — the one way the core runs a loop on several threads (threads.hpp).
// [0, count) is cut into chunks of `grain` elements (the last may be shorter); the chunking depends
// only on count and grain, so a reduction that keeps one partial result per chunk and combines them
// in chunk order gives bit-identical results for any thread count.
#pragma once
#include <atomic>
#include <cstddef>
#include <functional>

#include "straightest/base/progress.hpp"

namespace straightest::detail {

/// The number of chunks parallelFor cuts [0, count) into.
inline std::size_t chunkCount(std::size_t count, std::size_t grain) {
  return grain == 0 ? 0 : (count + grain - 1) / grain;
}

/// Calls body(chunk, begin, end) once for every chunk of [0, count) (grain > 0), on up to
/// threadCount() threads; the calling thread takes part. Bodies of different chunks may run at the
/// same time: they must write disjoint data. Only the calling thread calls `progress` (with `stage`
/// and the fraction of chunks done); when it returns false no new chunk starts, the running ones
/// finish, and parallelFor returns false. Returns true when every chunk ran.
bool parallelFor(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t chunk, std::size_t begin, std::size_t end)>& body,
                 const Progress& progress = {}, const char* stage = "");

/// Calls foreground() on the calling thread while one of the pool's workers runs background(stop), for
/// work that uses a core a serial step leaves idle (warm_up.hpp). Once foreground returns, `stop` is set
/// and background must return soon; this waits for it (a background that has not started by then never
/// does). Loops inside either run serially, since the pool is taken. With threadCount() == 1, or while
/// another loop holds the pool, only foreground runs. An exception from background is dropped (it is an
/// aid, never the result); one from foreground propagates once background has returned.
void runAlongside(const std::function<void(const std::atomic<bool>& stop)>& background,
                  const std::function<void()>& foreground);

}  // namespace straightest::detail
