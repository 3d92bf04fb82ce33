#include "supervisor.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <exception>

#include <spdlog/spdlog.h>

#include "child_process.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::cli {

std::map<std::string, double> parse_kills(const std::vector<std::string>& kills, const std::vector<Process>& procs,
                                          bool realtime) {
  std::map<std::string, double> kill_at;
  for (const auto& k : kills) {
    const auto at = k.rfind('@');
    double when = -1;
    try {
      when = at == std::string::npos ? -1 : std::stod(k.substr(at + 1));
    } catch (const std::exception&) {}
    if (when < 0) throw InputError("--kill " + k + ": expected PROCESS@SECONDS");
    const std::string name = k.substr(0, at);
    if (std::none_of(procs.begin(), procs.end(), [&](const Process& p) { return p.name == name; }))
      throw InputError("--kill " + k + ": no process '" + name + "' on this host");
    if (!realtime) throw InputError("--kill " + k + ": fault injection needs clock.mode realtime");
    kill_at[name] = when;
  }
  return kill_at;
}

ProcessSupervisor::ProcessSupervisor(std::vector<Process>& procs, LogRelay& relay, FaultClock& fault,
                                     const std::atomic<bool>& run_active, std::atomic<bool>& stop, bool realtime,
                                     std::map<std::string, double> kill_at)
    : procs_(procs),
      relay_(relay),
      fault_(fault),
      run_active_(run_active),
      stop_(stop),
      realtime_(realtime),
      kill_at_(std::move(kill_at)) {}

ProcessSupervisor::~ProcessSupervisor() {
  watching_ = false;
  if (watcher_.joinable()) watcher_.join();
}

void ProcessSupervisor::start(Process& p) {
  const int fd = relay_.open(p.service());
  p.pid = spawn(p.executable(), p.args, fd);
  ::close(fd);
  std::string cmd = p.executable();
  for (const auto& a : p.args) cmd += " " + a;
  relay_.note(p.service(), "started pid " + std::to_string(p.pid) + ": " + cmd);
}

void ProcessSupervisor::watch() {
  watcher_ = std::thread([this] {
    while (watching_) {
      const int64_t started = fault_.run_start_ns.load();
      for (auto& p : procs_) {
        inject_kill(p, started);
        reap(p);
        if (fatal_stop_ns_ && monotonic_ns() >= fatal_stop_ns_) stop_ = true;
        restart_if_due(p);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
}

void ProcessSupervisor::stop() {
  watching_ = false;
  if (watcher_.joinable()) watcher_.join();
  for (auto& p : procs_)
    if (p.pid > 0) cli::stop(p.pid), p.pid = 0;
}

std::optional<ProcessSupervisor::Exit> ProcessSupervisor::first_death() const {
  std::lock_guard lk(exits_mu_);
  return first_death_;
}

std::optional<int> ProcessSupervisor::await_exit(const std::string& service, int64_t timeout_ns) const {
  const int64_t until = monotonic_ns() + timeout_ns;
  for (;;) {
    {
      std::lock_guard lk(exits_mu_);
      const auto it = exits_.find(service);
      if (it != exits_.end()) return it->second;
    }
    if (!watcher_.joinable() || monotonic_ns() >= until) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void ProcessSupervisor::inject_kill(Process& p, int64_t started_ns) {
  auto k = kill_at_.find(p.name);
  if (!started_ns || k == kill_at_.end() || p.pid <= 0 ||
      monotonic_ns() - started_ns < static_cast<int64_t>(k->second * 1e9))
    return;
  ::kill(p.pid, SIGKILL);
  fault_.killed_ns = monotonic_ns();
  killed_ = p.name;
  spdlog::warn("fault injection: killed {} at {:.2f} s", p.service(), k->second);
  kill_at_.erase(k);
}

void ProcessSupervisor::reap(Process& p) {
  int status = 0;
  if (p.pid <= 0 || !exited(p.pid, status)) return;
  relay_.note(p.service(), "pid " + std::to_string(p.pid) + " exited with code " + std::to_string(status));
  p.pid = 0;
  {
    std::lock_guard lk(exits_mu_);
    exits_[p.service()] = status;
  }
  const bool restart =
      realtime_ && run_active_ && (p.restart == "always" || (status != 0 && p.restart == "on_failure"));
  if (restart) {
    // restart_delay (systemd's RestartSec): the restart is due that long after the death.
    p.restart_at_ns = monotonic_ns() + p.restart_delay_ns;
    spdlog::warn("{} exited with code {}: restart in {:.2f} s", p.service(), status, p.restart_delay_ns * 1e-9);
  } else if (status != 0 && !first_death()) {
    {
      std::lock_guard lk(exits_mu_);
      first_death_ = Exit{p.service(), status};
    }
    // Realtime: the run goes on for kFatalGraceNs, so that the recording shows how the
    // others reacted (their controllers' holds), then fails. Lockstep: at once.
    if (realtime_ && fault_.run_start_ns.load())
      fatal_stop_ns_ = monotonic_ns() + kFatalGraceNs;
    else
      stop_ = true;
  }
}

void ProcessSupervisor::restart_if_due(Process& p) {
  if (!p.restart_at_ns || monotonic_ns() < p.restart_at_ns || !run_active_) return;
  p.restart_at_ns = 0;
  start(p);
  if (fault_.killed_ns.load() && !fault_.respawned_ns.load() && p.name == killed_) fault_.respawned_ns = monotonic_ns();
  ++p.restarts;
  spdlog::warn("{}: restarted ({} restarts)", p.service(), p.restarts);
}

}  // namespace plexus::cli
