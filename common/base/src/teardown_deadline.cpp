#include "plexus/base/teardown_deadline.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include <spdlog/spdlog.h>

namespace plexus {
namespace {

struct Deadline {
  std::atomic<int64_t> due_ns{0};  // steady clock; 0: not armed
  std::atomic<int> rc{0};
  std::atomic<double> seconds{0};
  std::string who;  // set once, before the thread starts
  std::once_flag started;
};

Deadline& deadline() {
  static Deadline* d = new Deadline;  // never destroyed: the watcher may outlive main()
  return *d;
}

int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

int exit_within(int rc, double seconds, const std::string& who) {
  Deadline& d = deadline();
  d.rc = rc;
  d.seconds = seconds;
  d.due_ns = now_ns() + static_cast<int64_t>(std::llround(seconds * 1e9));
  std::call_once(d.started, [&d, &who] {
    d.who = who;
    std::thread([&d] {
      for (;;) {
        const int64_t left = d.due_ns.load() - now_ns();
        if (left <= 0) break;
        std::this_thread::sleep_for(std::chrono::nanoseconds(left));
      }
      std::fprintf(
          stderr,
          "%s: teardown did not finish within %g s of the end (a DDS vendor's shutdown hung): exiting without it\n",
          d.who.c_str(), d.seconds.load());
      spdlog::apply_all([](const std::shared_ptr<spdlog::logger>& l) { l->flush(); });
      std::fflush(nullptr);
      _exit(d.rc.load());
    }).detach();
  });
  return rc;
}

}  // namespace plexus
