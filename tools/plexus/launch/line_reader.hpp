// Lines from a pipe, with a timeout: the two ends of a remote share's ssh session
// (remote_protocol.hpp) read each other's lines with it.
#pragma once

#include <string>

namespace plexus::cli {

class LineReader {
 public:
  enum class Result { line, timeout, closed };
  explicit LineReader(int fd) : fd_(fd) {}
  /// The next line (without its newline), waiting at most `timeout_ms` (< 0: forever).
  /// A last line without a newline is returned before `closed`.
  Result next(std::string& line, int timeout_ms);
  /// Only what is already buffered or readable now (no wait).
  Result poll_line(std::string& line) { return next(line, 0); }
  int fd() const { return fd_; }

 private:
  int fd_;
  std::string buf_;
  bool eof_ = false;
};

/// Writes all of `line` and a newline; false when the reader is gone (EPIPE; SIGPIPE must be ignored).
bool write_line(int fd, const std::string& line);

}  // namespace plexus::cli
