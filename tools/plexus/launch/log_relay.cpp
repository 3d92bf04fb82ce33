#include "log_relay.hpp"

#include "plexus/base/bounded_name.hpp"
#include "plexus/base/input_error.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace plexus::cli {

namespace {
/// "localisation_observer observer" -> "localisation_observer_observer.log"; a process named
/// after many components is cut to Linux's 255-byte file names (bounded_name).
std::string file_name(std::string name) {
  for (char& c : name)
    if (c == ' ' || c == '/' || c == ',') c = '_';
  return bounded_name(name, 255 - 4) + ".log";
}
}  // namespace

struct LogRelay::Impl {
  struct Source {
    std::string name;
    int fd = -1;
    std::FILE* file = nullptr;
    std::string partial;  // bytes after the last newline
    std::string last;     // the last non-empty line
  };
  std::filesystem::path dir;
  StatusConsole* console = nullptr;
  mutable std::mutex mu;  // guards sources (added by the launcher, read by the thread)
  std::vector<Source> sources;
  std::atomic<bool> running{true};
  std::thread thread;
  std::size_t width = 8;  // prefix column width

  void emit(Source& s, const std::string& line) {
    if (!line.empty()) s.last = line;
    if (s.file) {
      std::fwrite(line.data(), 1, line.size(), s.file);
      std::fputc('\n', s.file);
      std::fflush(s.file);
    }
    std::string out = s.name;
    out.resize(std::max(width, s.name.size()), ' ');
    console->line(out + " | " + line);
  }

  void close_source(Source& s) {
    if (!s.partial.empty()) emit(s, s.partial);
    s.partial.clear();
    ::close(s.fd);
    s.fd = -1;
    if (s.file) std::fclose(s.file);
    s.file = nullptr;
  }

  void loop() {
    std::vector<pollfd> fds;
    char buf[4096];
    while (running) {
      {
        std::lock_guard lk(mu);
        fds.clear();
        for (const auto& s : sources)
          if (s.fd >= 0) fds.push_back({s.fd, POLLIN, 0});
      }
      if (fds.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        continue;
      }
      if (::poll(fds.data(), fds.size(), 100) <= 0) continue;
      std::lock_guard lk(mu);
      for (const auto& p : fds) {
        if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
        for (auto& s : sources) {
          if (s.fd != p.fd) continue;
          const ssize_t n = ::read(s.fd, buf, sizeof buf);
          if (n <= 0) {
            close_source(s);
            break;
          }
          s.partial.append(buf, static_cast<std::size_t>(n));
          std::size_t start = 0, nl;
          while ((nl = s.partial.find('\n', start)) != std::string::npos) {
            emit(s, s.partial.substr(start, nl - start));
            start = nl + 1;
          }
          s.partial.erase(0, start);
          break;
        }
      }
    }
  }
};

LogRelay::LogRelay(const std::filesystem::path& dir, StatusConsole& console) : impl_(std::make_unique<Impl>()) {
  impl_->dir = dir;
  impl_->console = &console;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the log folder (" + ec.message() + ")");
  impl_->thread = std::thread([this] { impl_->loop(); });
}

LogRelay::~LogRelay() {
  drain(500);
  impl_->running = false;
  if (impl_->thread.joinable()) impl_->thread.join();
  for (auto& s : impl_->sources)
    if (s.fd >= 0) impl_->close_source(s);
}

int LogRelay::open(const std::string& name) {
  int p[2];
  if (::pipe2(p, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe for " + name + "'s output");
  Impl::Source s;
  s.name = name;
  s.fd = p[0];
  const std::filesystem::path path = impl_->dir / file_name(name);
  s.file = std::fopen(path.c_str(), "a");
  const int open_error = errno;
  std::lock_guard lk(impl_->mu);
  if (!s.file) {
    // At a process's first start: an error (its log would be lost). At a restart (the file
    // opened before; the disk may have filled since): the output still reaches the console.
    const std::string why = "cannot open " + path.string() + " for " + name + "'s output: " + std::strerror(open_error);
    const bool restart = std::any_of(impl_->sources.begin(), impl_->sources.end(),
                                     [&](const Impl::Source& o) { return o.name == name; });
    if (!restart) {
      ::close(p[0]);
      ::close(p[1]);
      throw std::runtime_error(why);
    }
    impl_->console->line(name + " | " + why);
  }
  impl_->width = std::max(impl_->width, name.size());
  impl_->sources.push_back(std::move(s));
  return p[1];
}

void LogRelay::note(const std::string& name, const std::string& line) {
  std::lock_guard lk(impl_->mu);
  for (auto it = impl_->sources.rbegin(); it != impl_->sources.rend(); ++it)
    if (it->name == name) {
      std::FILE* f = std::fopen((impl_->dir / file_name(name)).c_str(), "a");
      if (!f) return;
      std::fprintf(f, "-- %s\n", line.c_str());
      std::fclose(f);
      return;
    }
}

std::string LogRelay::last_line(const std::string& name, int wait_ms) const {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(wait_ms);
  for (;;) {
    {
      std::lock_guard lk(impl_->mu);
      const auto it = std::find_if(impl_->sources.rbegin(), impl_->sources.rend(),  // a restart's newest
                                   [&](const Impl::Source& s) { return s.name == name; });
      if (it == impl_->sources.rend()) return {};
      if (it->fd < 0 || std::chrono::steady_clock::now() >= end) return it->last;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

void LogRelay::drain(int timeout_ms) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    {
      std::lock_guard lk(impl_->mu);
      bool open = false;
      for (const auto& s : impl_->sources) open = open || s.fd >= 0;
      if (!open) return;
    }
    if (std::chrono::steady_clock::now() >= end) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace plexus::cli
