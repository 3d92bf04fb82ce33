// The remote end of a share started over ssh (`plexus launch --remote`): answers the
// launcher on stdin/stdout (remote_protocol.hpp) and stops the share when the session ends.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include "line_reader.hpp"
#include "remote_protocol.hpp"

namespace plexus::cli {

class RemoteSession {
 public:
  /// Prints the hello line (the launcher checks the version from it).
  explicit RemoteSession(const std::string& version);
  ~RemoteSession();
  RemoteSession(const RemoteSession&) = delete;
  RemoteSession& operator=(const RemoteSession&) = delete;

  /// The launcher's request. Throws InputError when it is missing or malformed.
  RemoteRequest read_request();
  /// Sends `ready`, answers the clock exchanges (adding `injection_ns` to this clock's
  /// readings) and returns true at `go`; false when the launcher closed the session.
  bool ready_and_wait_go(const RemoteReady& ready, int64_t injection_ns);
  /// From now on, a thread answers keepalives with `running()` of `expected` processes
  /// and sets `stop` when stdin closes or stays silent for kSilenceLimitS.
  void watch(std::atomic<bool>& stop, int expected, std::function<int()> running);
  /// Why the watcher set `stop` ("" if it did not).
  std::string ended() const;

 private:
  LineReader in_{0};
  std::mutex out_mu_;
  std::thread watcher_;
  std::atomic<bool> quit_{false};
  mutable std::mutex why_mu_;
  std::string why_;
  bool send(const std::string& line);
};

}  // namespace plexus::cli
