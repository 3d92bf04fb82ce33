// plexus launch's log collector: every child's stdout and stderr go through a pipe to one
// relay thread, which prefixes each line with the process name on the launcher's stderr
// and appends it to <run folder>/logs/<process>.log (a restarted process appends to the
// same file). Children log at a rate limit, so the pipes never fill.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "status_console.hpp"

namespace plexus::cli {

class LogRelay {
 public:
  /// Log files go to `dir` (created); every line is also printed, prefixed, on `console`.
  LogRelay(const std::filesystem::path& dir, StatusConsole& console);
  ~LogRelay();
  LogRelay(const LogRelay&) = delete;
  LogRelay& operator=(const LogRelay&) = delete;

  /// A new output for process `name`: returns the write end of a pipe (close-on-exec) for
  /// the child's stdout and stderr. Close it in the launcher once the child is started.
  int open(const std::string& name);
  /// Appends a launcher line to `name`'s log file only ("-- started pid 42: ...").
  void note(const std::string& name, const std::string& line);
  /// The last non-empty line process `name` printed ("" if none): a process that fails
  /// prints its one-line error last. Waits up to `wait_ms` for its output's end of file
  /// (complete at once after drain()).
  std::string last_line(const std::string& name, int wait_ms = 0) const;
  /// Waits (up to `timeout_ms`) until every output opened so far reached end of file, so
  /// the children's last lines are printed before the launcher's own verdict.
  void drain(int timeout_ms = 2000);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plexus::cli
