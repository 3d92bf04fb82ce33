// This process's CPUs: which it may run on, and running on one of them for a while (the
// latency commands place their measured programs with it; children inherit the affinity).
#pragma once

#include <sched.h>

#include <vector>

namespace plexus::cli {

/// The CPUs this process may run on, in order; empty if they cannot be read.
std::vector<int> allowed_cpus();

/// While it lives, this process (and so every child it starts) runs on CPU `cpu` (-1: as is).
class PinnedTo {
 public:
  explicit PinnedTo(int cpu);
  ~PinnedTo();
  PinnedTo(const PinnedTo&) = delete;
  PinnedTo& operator=(const PinnedTo&) = delete;

 private:
  cpu_set_t saved_{};
  bool pinned_ = false;
};

}  // namespace plexus::cli
