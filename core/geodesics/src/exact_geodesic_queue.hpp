// exact_geodesic_queue.hpp (private) — the window propagation's priority queue: a bucket queue (Dial's)
// whose buckets are intervals of keys of one fixed width, popped in the order of their intervals.
//
// The propagation pops every window it creates, tens of millions on large meshes, so the queue's cost per
// entry is much of the propagation's. Its keys are monotone (a window's least distance is at least that
// of the window it came from, a vertex's distance at least that of the window that set it), and an entry
// is queued, at most, a few edge lengths beyond the last key popped; so a ring of buckets over the keys
// just ahead of the front holds nearly all of them, and each entry is written once and read once. (The
// radix heap this replaced moved each entry between its buckets a few to tens of times.) Entries of one bucket pop
// newest first, in any order of their keys: the width is the order's resolution. The propagation stays exact in any pop
// order (every window it drops is dominated by a path it measured); the order only decides how much it prunes: the
// finer the width, the closer the window count to the exact order's, and a coarse order makes several times more
// (docs/BENCHMARKS.md).
//
// A bucket is a stack of fixed-size chunks taken from a shared pool (a free list), so memory follows the
// entries queued rather than the largest each bucket ever held. An entry beyond the ring's reach waits in
// a far heap (keys more than 4096 widths ahead: 64 mean edges in the propagation, so only on meshes of very
// unequal edges), moved into the ring when the front comes within its reach.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "straightest/base/huge_page_allocator.hpp"

namespace straightest::detail {

template <typename Payload>
class MinQueue {
 public:
  /// width: the key resolution (> 0; otherwise 1): keys in one interval of this width pop in any order.
  explicit MinQueue(double width) : inverse_(width > 0 && std::isfinite(1 / width) ? 1 / width : 1.0) {}

  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  /// The most entries queued at once so far.
  size_t peak() const { return peak_; }

  /// Queues payload with key (≥ 0; a key in an interval before the last one popped counts as in that one).
  void push(double key, const Payload& payload) {
    const double scaled = key * inverse_;
    // Through signed integers (slots stay below kMaxSlot < 2⁶³, so the same values): x86-64 converts
    // between double and uint64 only by a branch and two conversions; and the front's slot as a double kept.
    const uint64_t slot = !(scaled >= currentKey_) ? current_  // before the front, or NaN
                          : scaled >= kMaxSlot     ? kMaxSlot
                                                   : static_cast<uint64_t>(static_cast<int64_t>(scaled));
    peak_ = std::max(peak_, ++size_);
    if (slot - current_ < kRing) {
      pushToBucket(slot & (kRing - 1), payload);
      return;
    }
    far_.push_back(Far{slot, payload});
    std::push_heap(far_.begin(), far_.end(), laterSlot);
  }

  /// Removes an entry of least key (up to the width; ties: any) and returns its payload. Not on an empty
  /// queue.
  Payload pop() {
    for (;;) {
      Bucket& bucket = buckets_[current_ & (kRing - 1)];
      if (bucket.top >= 0) {
        Chunk& chunk = chunks_[bucket.top];
        const Payload payload = chunk.items[--bucket.count];
        if (bucket.count == 0) {  // the chunk below (if any) is full
          const int32_t emptied = bucket.top;
          bucket.top = chunk.below;
          bucket.count = kChunk;
          chunk.below = free_;
          free_ = emptied;
        }
        --size_;
        --inRing_;
        return payload;
      }
      if (inRing_ == 0) current_ = far_.front().slot;  // an empty ring: jump to the far heap's nearest
      else ++current_;
      currentKey_ = static_cast<double>(static_cast<int64_t>(current_));
      // The far heap's entries now within the ring's reach move into it.
      while (!far_.empty() && far_.front().slot - current_ < kRing) {
        pushToBucket(far_.front().slot & (kRing - 1), far_.front().payload);
        std::pop_heap(far_.begin(), far_.end(), laterSlot);
        far_.pop_back();
      }
    }
  }

 private:
  static constexpr uint64_t kRing = 4096;  // buckets in the ring (a power of 2)
  static constexpr int kChunk = 16;        // entries per chunk
  static constexpr double kMaxSlot = 4.0e18;

  /// Aligned to a cache line, so that a 64-byte entry (the propagation's window) is one line, not two.
  struct alignas(64) Chunk {
    Payload items[kChunk];
    int32_t below = -1;  // the next chunk of the same bucket's stack (full), or of the free list
  };
  /// A bucket: its stack's top chunk (−1: empty) and how many entries that one holds (the chunks below it
  /// are full). Kept here, not in the chunk, so that a push reads no chunk but the line it writes.
  struct Bucket {
    int32_t top = -1;
    int32_t count = 0;
  };
  struct Far {
    uint64_t slot;
    Payload payload;
  };

  void pushToBucket(size_t b, const Payload& payload) {
    Bucket& bucket = buckets_[b];
    if (bucket.top < 0 || bucket.count == kChunk) {
      int32_t fresh = free_;
      if (fresh >= 0) {
        free_ = chunks_[fresh].below;
      } else {
        fresh = static_cast<int32_t>(chunks_.size());
        chunks_.emplace_back();
      }
      chunks_[fresh].below = bucket.top;
      bucket.top = fresh;
      bucket.count = 0;
    }
    chunks_[bucket.top].items[bucket.count++] = payload;
    ++inRing_;
  }

  static bool laterSlot(const Far& a, const Far& b) { return a.slot > b.slot; }

  const double inverse_;
  HugeVector<Chunk> chunks_;
  std::vector<Bucket> buckets_ = std::vector<Bucket>(kRing);
  std::vector<Far> far_;     // a min-heap by slot (laterSlot) of the entries beyond the ring's reach
  int32_t free_ = -1;        // the free list of chunks
  uint64_t current_ = 0;     // the bucket (slot) being popped
  double currentKey_ = 0.0;  // current_ as a double
  size_t size_ = 0, inRing_ = 0, peak_ = 0;
};

}  // namespace straightest::detail
