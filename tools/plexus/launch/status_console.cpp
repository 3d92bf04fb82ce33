#include "status_console.hpp"

#include <unistd.h>

#include <spdlog/sinks/base_sink.h>

#include <cstdio>

#include "plexus/base/clock.hpp"

namespace plexus::cli {

StatusConsole::StatusConsole(bool status_enabled, double plain_interval_s)
    : enabled_(status_enabled),
      tty_(isatty(STDERR_FILENO) == 1),
      plain_interval_ns_(static_cast<int64_t>(plain_interval_s * 1e9)) {}

StatusConsole::~StatusConsole() { clear(); }

void StatusConsole::erase_locked() {
  if (drawn_) std::fputs("\r\033[K", stderr);
  drawn_ = false;
}

void StatusConsole::line(const std::string& text) {
  std::lock_guard lk(mu_);
  erase_locked();
  std::fputs(text.c_str(), stderr);
  std::fputc('\n', stderr);
  if (tty_ && enabled_ && !status_.empty()) {
    std::fputs(status_.c_str(), stderr);
    drawn_ = true;
  }
  std::fflush(stderr);
}

void StatusConsole::status(const std::string& text) {
  if (!enabled_) return;
  const std::string hosts = hosts_ ? hosts_() : std::string();
  std::lock_guard lk(mu_);
  status_ = hosts.empty() ? text : text + " | hosts: " + hosts;
  if (tty_) {
    erase_locked();
    std::fputs(status_.c_str(), stderr);
    drawn_ = true;
  } else {
    const int64_t now = monotonic_ns();
    if (now < next_plain_ns_) return;
    next_plain_ns_ = now + plain_interval_ns_;
    std::fprintf(stderr, "%s\n", status_.c_str());
  }
  std::fflush(stderr);
}

void StatusConsole::clear() {
  std::lock_guard lk(mu_);
  erase_locked();
  status_.clear();
  std::fflush(stderr);
}

namespace {
/// An spdlog sink that hands each formatted line to the console.
class ConsoleSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  explicit ConsoleSink(StatusConsole& console) : console_(console) {}

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    spdlog::memory_buf_t buf;
    formatter_->format(msg, buf);
    std::string line(buf.data(), buf.size());
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    console_.line(line);
  }
  void flush_() override {}

 private:
  StatusConsole& console_;
};
}  // namespace

ConsoleLogging::ConsoleLogging(StatusConsole& console) {
  auto logger = spdlog::default_logger();
  saved_ = logger->sinks();
  auto sink = std::make_shared<ConsoleSink>(console);
  sink->set_pattern("%Y-%m-%dT%H:%M:%S.%e %l [%n] %v");
  logger->sinks() = {sink};
}

ConsoleLogging::~ConsoleLogging() { spdlog::default_logger()->sinks() = saved_; }

}  // namespace plexus::cli
