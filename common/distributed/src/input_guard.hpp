// The edge check every remote signal passes before a component sees it (docs/architecture.md,
// "Bad input"): WireSignal::decode refuses a sample with a negative time, a non-finite or
// out-of-range member or a wrong joint count. A refused sample is dropped as if it never
// arrived: in lockstep the step then waits for a valid one and times out naming the signal;
// in realtime the input goes stale and the consumer falls back to its safe output.
// Estimator state never sees it.
#pragma once

#include <cstdint>
#include <string>

#include "plexus/base/logging.hpp"
#include "plexus/distributed/wire.hpp"

namespace plexus::distributed::detail {

/// Counts and logs (at most once a second, with the number held back) the samples one
/// host refuses. No allocation unless a line is actually logged.
class InputGuard {
 public:
  explicit InputGuard(std::string host) : host_(std::move(host)) {}

  /// Decodes `message` (of `wire`'s type) into `s`; false (counted, maybe logged) if it was refused.
  bool accept(const WireSignal& wire, const void* message, scenario::SignalSample& s);
  uint64_t rejected() const { return rejected_; }

 private:
  std::string host_;
  RateLimiter limiter_;
  uint64_t rejected_ = 0;
};

}  // namespace plexus::distributed::detail
