// The edge check every remote signal passes before a component sees it (issue 8: "rejects
// non-finite or out-of-range input fields at the edge, counting and logging them at a rate
// limit"). A rejected sample is dropped as if it never arrived: in lockstep the step then
// waits for a valid one and times out naming the signal; in realtime the input goes stale
// and the consumer falls back to its safe output. Estimator state never sees it.
#pragma once

#include <cstdint>
#include <string>

#include "plexus/base/logging.hpp"
#include "signal_codec.hpp"

namespace plexus::distributed::detail {

/// Counts and logs (at most once a second, with the number held back) the samples one
/// host refuses. No allocation unless a line is actually logged.
class InputGuard {
 public:
  explicit InputGuard(std::string host) : host_(std::move(host)) {}

  /// Decodes `m` for `spec`; false (counted, maybe logged) if it was refused.
  bool accept(const msg::Signal& m, const scenario::SignalSpec& spec, scenario::SignalSample& s);
  uint64_t rejected() const { return rejected_; }

 private:
  std::string host_;
  RateLimiter limiter_;
  uint64_t rejected_ = 0;
};

}  // namespace plexus::distributed::detail
