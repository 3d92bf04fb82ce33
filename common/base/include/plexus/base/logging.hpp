// Logging: spdlog, one line per event, the service (and robot) in every line.
#pragma once

#include <spdlog/spdlog.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace plexus {

/// Creates the process logger named `service` (with `robot` if not empty), writing to
/// stderr with the pattern `time level [service/robot] message`, and makes it the
/// default logger. `level` is an spdlog level name (trace, debug, info, warn, error,
/// critical, off); an unknown name throws InputError.
std::shared_ptr<spdlog::logger> init_logging(std::string_view service, std::string_view robot = {},
                                             std::string_view level = "info");

/// A logger for one part of a program ("scenario", "scenario.unicycle"): the same stderr
/// sink and line format as init_logging's, at the default logger's level. Created on first
/// use and registered, so every caller with the same name shares it.
std::shared_ptr<spdlog::logger> named_logger(const std::string& name);

/// Parses an spdlog level name; throws InputError naming `origin` for an unknown one.
spdlog::level::level_enum parse_log_level(std::string_view name, std::string_view origin);

/// Lets through at most one event per `interval_ns` and counts the ones it holds back,
/// so a loop can log a recurring problem without flooding. Lock-free, no allocation.
class RateLimiter {
 public:
  explicit RateLimiter(int64_t interval_ns = 1'000'000'000) : interval_ns_(interval_ns) {}

  /// True if the caller may log now; `suppressed` receives the number of events
  /// held back since the last one let through.
  bool allow(int64_t now_ns, uint64_t& suppressed);

 private:
  int64_t interval_ns_;
  std::atomic<int64_t> next_ns_{INT64_MIN};
  std::atomic<uint64_t> held_{0};
};

}  // namespace plexus
