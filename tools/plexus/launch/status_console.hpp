// The launcher's stderr: log lines from the children (LogRelay) and a live status line
// that stays at the bottom. On a terminal the status line is redrawn in place (each log
// line clears it first and redraws it after); elsewhere (CI logs, files) it is printed as
// an ordinary line every `plain_interval_s`. Thread-safe.
#pragma once

#include <spdlog/spdlog.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace plexus::cli {

class StatusConsole {
 public:
  /// `status_enabled`: false for --quiet (log lines still pass through).
  explicit StatusConsole(bool status_enabled, double plain_interval_s = 10.0);
  ~StatusConsole();

  /// Prints one log line (a newline is added).
  void line(const std::string& text);
  /// Replaces the status line.
  void status(const std::string& text);
  /// Removes the status line (before the final report).
  void clear();
  /// Appended to every status line after " | hosts: " (plexus launch over ssh: per-host
  /// health, remote_share.hpp). Set before the status line is first drawn.
  void set_hosts(std::function<std::string()> hosts) { hosts_ = std::move(hosts); }

 private:
  void erase_locked();
  std::mutex mu_;
  bool enabled_, tty_;
  int64_t plain_interval_ns_, next_plain_ns_ = 0;
  std::string status_;
  std::function<std::string()> hosts_;
  bool drawn_ = false;
};

/// While alive, the process's default spdlog logger writes through `console` (so the
/// launcher's own warnings do not tear the status line); restores the previous sinks.
class ConsoleLogging {
 public:
  explicit ConsoleLogging(StatusConsole& console);
  ~ConsoleLogging();
  ConsoleLogging(const ConsoleLogging&) = delete;
  ConsoleLogging& operator=(const ConsoleLogging&) = delete;

 private:
  std::vector<std::shared_ptr<spdlog::sinks::sink>> saved_;
};

}  // namespace plexus::cli
