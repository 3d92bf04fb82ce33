#include "remote_session.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <sstream>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::cli {

RemoteSession::RemoteSession(const std::string& version) {
  std::signal(SIGPIPE, SIG_IGN);  // a write to a closed session fails with EPIPE instead
  send(hello_line(version));
}

RemoteSession::~RemoteSession() {
  quit_ = true;
  if (watcher_.joinable()) watcher_.join();
}

bool RemoteSession::send(const std::string& line) {
  std::lock_guard lk(out_mu_);
  return write_line(STDOUT_FILENO, line);
}

RemoteRequest RemoteSession::read_request() {
  std::string line;
  if (in_.next(line, static_cast<int>(kPreflightWaitS * 1000)) != LineReader::Result::line)
    throw InputError("--remote: no request from the launcher on stdin (this mode is for plexus launch over ssh)");
  return RemoteRequest::from_line(line, "--remote");
}

bool RemoteSession::ready_and_wait_go(const RemoteReady& ready, int64_t injection_ns) {
  if (!send(ready.to_line())) return false;
  for (std::string line;;) {
    if (in_.next(line, static_cast<int>(kPreflightWaitS * 1000)) != LineReader::Result::line) return false;
    if (line == "go") return true;
    if (line.rfind("ping ", 0) == 0) {
      const int64_t t2 = wall_time_ns() + injection_ns;
      std::ostringstream pong;
      pong << "pong " << line.substr(5) << ' ' << t2 << ' ' << wall_time_ns() + injection_ns;
      if (!send(pong.str())) return false;
    }
  }
}

void RemoteSession::watch(std::atomic<bool>& stop, int expected, std::function<int()> running) {
  watcher_ = std::thread([this, &stop, expected, running = std::move(running)] {
    auto end = [&](const std::string& why) {
      {
        std::lock_guard lk(why_mu_);
        why_ = why;
      }
      stop = true;
    };
    int64_t heard = monotonic_ns();
    for (std::string line; !quit_;) {
      const auto r = in_.next(line, 100);
      if (r == LineReader::Result::closed) return end("the launcher closed the session");
      if (r == LineReader::Result::line) {
        heard = monotonic_ns();
        if (line == "alive" && !send("status " + std::to_string(running()) + " " + std::to_string(expected)))
          return end("the session is gone");
      } else if (monotonic_ns() - heard > static_cast<int64_t>(kSilenceLimitS * 1e9)) {
        return end("no keepalive from the launcher for " + std::to_string(static_cast<int>(kSilenceLimitS)) + " s");
      }
    }
  });
}

std::string RemoteSession::ended() const {
  std::lock_guard lk(why_mu_);
  return why_;
}

}  // namespace plexus::cli
