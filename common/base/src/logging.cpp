#include "plexus/base/logging.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

#include "plexus/base/input_error.hpp"

namespace plexus {

spdlog::level::level_enum parse_log_level(std::string_view name, std::string_view origin) {
  for (int i = 0; i < spdlog::level::n_levels; ++i) {
    const auto lvl = static_cast<spdlog::level::level_enum>(i);
    const auto sv = spdlog::level::to_string_view(lvl);
    if (std::string_view(sv.data(), sv.size()) == name) return lvl;
  }
  if (name == "warn" || name == "warning") return spdlog::level::warn;
  if (name == "err") return spdlog::level::err;
  throw InputError(std::string(origin) + ": unknown log level '" + std::string(name) +
                   "' (expected trace, debug, info, warn, error, critical or off)");
}

namespace {
// One line format for every logger of every plexus program: ISO time, level, [source] text.
constexpr const char* kPattern = "%Y-%m-%dT%H:%M:%S.%e %^%-5l%$ [%n] %v";
}  // namespace

std::shared_ptr<spdlog::logger> named_logger(const std::string& name) {
  if (auto l = spdlog::get(name)) return l;
  auto logger = std::make_shared<spdlog::logger>(name, std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
  logger->set_pattern(kPattern);
  logger->set_level(spdlog::default_logger()->level());
  logger->flush_on(spdlog::level::warn);
  try {
    spdlog::register_logger(logger);
  } catch (const spdlog::spdlog_ex&) {  // registered by another thread meanwhile
    if (auto l = spdlog::get(name)) return l;
  }
  return logger;
}

std::shared_ptr<spdlog::logger> init_logging(std::string_view service, std::string_view robot, std::string_view level) {
  const auto lvl = parse_log_level(level, "--log-level");
  std::string tag(service);
  if (!robot.empty()) tag += "/" + std::string(robot);
  auto sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
  auto logger = std::make_shared<spdlog::logger>(tag, sink);
  logger->set_pattern(kPattern);
  logger->set_level(lvl);
  logger->flush_on(spdlog::level::warn);
  spdlog::set_default_logger(logger);
  return logger;
}

bool RateLimiter::allow(int64_t now_ns, uint64_t& suppressed) {
  int64_t next = next_ns_.load(std::memory_order_relaxed);
  if (now_ns >= next && next_ns_.compare_exchange_strong(next, now_ns + interval_ns_)) {
    suppressed = held_.exchange(0);
    return true;
  }
  held_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

}  // namespace plexus
