// Samples handed from the threads that take them (a recorder's readers, the lockstep
// clock) to the thread that writes them: push() appends to the pending batch under a
// short lock, take() swaps it for the writer's emptied one. Neither allocates once both
// batches have grown to a batch's size, and neither does I/O under the lock.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>

#include "recording.hpp"

namespace plexus::cli {

class SampleQueue {
 public:
  void push(int64_t topic_id, int64_t receive_time_ns, const msg::StampHeader* header, const unsigned char* cdr,
            std::size_t size) {
    std::lock_guard lk(mu_);
    pending_.add(topic_id, receive_time_ns, header, cdr, size);
    pushed_.fetch_add(1, std::memory_order_relaxed);
  }
  /// `batch` (cleared first) now holds every sample pushed since the last take().
  void take(SampleBatch& batch) {
    batch.clear();
    std::lock_guard lk(mu_);
    std::swap(batch, pending_);
  }
  uint64_t pushed() const { return pushed_.load(std::memory_order_relaxed); }

 private:
  std::mutex mu_;
  SampleBatch pending_;
  std::atomic<uint64_t> pushed_{0};
};

}  // namespace plexus::cli
