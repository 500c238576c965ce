// exact_geodesic_queue.hpp (private) — the window propagation's priority queue: payloads in a pool whose
// slots are reused, ordered by a 4-ary min-heap of (key, slot) pairs.
//
// The propagation pops every window it creates, tens of millions on large meshes, and the pop dominated
// its profile: a 4-ary heap is half as deep as a binary one and a node's four children share a cache line
// (16-byte entries), and the heap moves 16 bytes per step rather than the payload. After a pop the next
// top's payload is prefetched, since the caller works on the popped one for a while.
#pragma once
#include <cstdint>
#include <vector>

namespace straightest::detail {

template <typename Payload>
class MinQueue {
 public:
  bool empty() const { return heap_.empty(); }
  size_t size() const { return heap_.size(); }

  void push(double key, const Payload& payload) {
    int32_t slot;
    if (free_.empty()) {
      slot = static_cast<int32_t>(pool_.size());
      pool_.push_back(payload);
    } else {
      slot = free_.back();
      free_.pop_back();
      pool_[slot] = payload;
    }
    // Sift up.
    size_t i = heap_.size();
    heap_.push_back(Entry{key, slot});
    while (i > 0) {
      const size_t parent = (i - 1) / 4;
      if (!(key < heap_[parent].key)) break;
      heap_[i] = heap_[parent];
      i = parent;
    }
    heap_[i] = Entry{key, slot};
  }

  /// Removes the entry of least key (ties: any) and returns its payload. Not on an empty queue.
  Payload pop() {
    const int32_t slot = heap_.front().slot;
    const Entry last = heap_.back();
    heap_.pop_back();
    const size_t n = heap_.size();
    if (n > 0) {
      // Sift `last` down from the root.
      size_t i = 0;
      for (;;) {
        const size_t first = 4 * i + 1;
        if (first >= n) break;
        size_t best = first;
        const size_t end = first + 4 < n ? first + 4 : n;
        for (size_t c = first + 1; c < end; ++c)
          if (heap_[c].key < heap_[best].key) best = c;
        if (!(heap_[best].key < last.key)) break;
        heap_[i] = heap_[best];
        i = best;
      }
      heap_[i] = last;
#if defined(__GNUC__) || defined(__clang__)
      __builtin_prefetch(&pool_[heap_.front().slot]);
#endif
    }
    free_.push_back(slot);
    return pool_[slot];
  }

 private:
  struct Entry {
    double key;
    int32_t slot;
  };
  std::vector<Entry> heap_;
  std::vector<Payload> pool_;
  std::vector<int32_t> free_;
};

}  // namespace straightest::detail
