// The last `capacity` records of a loop, newest first by age (0: the newest), in storage
// allocated once at construction: push() and at() do not allocate. Used where an estimate is
// revised over its recent past (the ICR EKF's rewound reset, the revisable ICR odometry).
#pragma once

#include <algorithm>
#include <vector>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

template <class Record>
class HistoryRing {
 public:
  /// capacity >= 0 (0: keeps nothing); throws std::invalid_argument naming `where`.
  HistoryRing(int capacity, const char* where) {
    if (capacity < 0) validation::fail(where, "history capacity", ">= 0", capacity);
    records_.resize(static_cast<std::size_t>(capacity));
  }

  int capacity() const { return static_cast<int>(records_.size()); }
  /// Records kept, <= capacity().
  int size() const { return kept_; }
  void clear() { kept_ = 0; }

  /// The slot of a new newest record (the oldest is overwritten when full); capacity() > 0.
  Record& push() {
    head_ = (head_ + 1) % capacity();
    kept_ = std::min(kept_ + 1, capacity());
    return records_[static_cast<std::size_t>(head_)];
  }

  /// The record `age` steps before the newest, 0 <= age < size().
  Record& at(int age) { return records_[index(age)]; }
  const Record& at(int age) const { return records_[index(age)]; }

 private:
  std::size_t index(int age) const { return static_cast<std::size_t>((head_ - age + capacity()) % capacity()); }

  std::vector<Record> records_;
  int head_ = -1;
  int kept_ = 0;
};

}  // namespace plexus::algorithms
