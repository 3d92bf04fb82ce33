// plexus launch in lockstep, on the clock's host: the live status line (progress, step rate,
// the slowest producer), once a second, and each producer's step response over the run.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plexus/distributed/lockstep.hpp"
#include "plexus/scenario/scenario.hpp"
#include "status_console.hpp"

namespace plexus::cli {

class LockstepStatus {
 public:
  /// `start_ns`: monotonic time of the first step. `producer_offset_us`: for a producer on
  /// another host, that host's clock offset, by which its responses are corrected (it stamps
  /// them with its own clock).
  LockstepStatus(const scenario::Scenario& sc, distributed::LockstepClock& clock, StatusConsole& console,
                 int64_t start_ns, std::map<std::string, double> producer_offset_us);

  /// The clock's step observer (step k of n): at most once a second, and at the last step.
  void observe(int64_t k, int64_t n);
  /// launch.json's "response": per producer, its samples, the mean of its per-second p50
  /// and its worst per-second p99, and the clock offset they were corrected by.
  nlohmann::ordered_json response() const;

 private:
  struct Response {  // a producer's step response, over the run
    uint64_t samples = 0;
    int windows = 0;
    double p50_sum = 0, worst_p99 = 0;
  };
  void accumulate();
  void show(int64_t k, int64_t n, double rate);

  const scenario::Scenario& sc_;
  distributed::LockstepClock& clock_;
  StatusConsole& console_;
  std::map<std::string, double> producer_offset_us_;
  std::vector<distributed::LockstepClock::ProducerStatus> status_;
  std::map<std::string, Response> responses_;
  int64_t status_at_, steps_at_ = 0;
};

}  // namespace plexus::cli
