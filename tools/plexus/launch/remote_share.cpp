#include "remote_share.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "launch_plan.hpp"
#include "line_reader.hpp"
#include "piped_process.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "preflight.hpp"

namespace plexus::cli {
namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

}  // namespace

struct RemoteShares::Impl {
  struct Host {
    std::string name, destination, address;
    PipedProcess proc;
    std::unique_ptr<LineReader> out, err;
    std::vector<std::string> err_tail;   // its last stderr lines, for the error message
    std::vector<std::string> processes;  // service names of its processes (log prefixes)
    ClockOffset offset;
    double ready_s = 0;
    // Run time, guarded by mu.
    std::map<std::string, int> relay_fd;  // process -> write end of its LogRelay pipe
    int running = 0, expected = 0;
    int64_t alive_sent_ns = 0, heard_ns = 0, rtt_ns = -1;
    bool reaped = false;
    int exit_code = -1;
    std::string state = "starting";  // starting | running | done | lost
    std::thread monitor;
  };
  Impl(const scenario::Scenario& scenario, std::string local_host, RemoteShareOptions options)
      : sc(scenario), local(std::move(local_host)), o(std::move(options)) {}
  const scenario::Scenario& sc;
  std::string local;
  RemoteShareOptions o;
  std::vector<std::unique_ptr<Host>> hosts;
  int local_expected = 0;
  mutable std::mutex mu;
  std::condition_variable reaped_cv;
  std::string failure;
  std::atomic<bool> stopping{false};
  std::atomic<bool>* stop_flag = nullptr;
  bool stopped = false;
  int64_t t0 = monotonic_ns();

  std::string who(const Host& h) const { return "host " + h.name + " (" + h.destination + ")"; }

  void note_stderr(Host& h, const std::string& line) {
    if (line.empty()) return;
    h.err_tail.push_back(line);
    if (h.err_tail.size() > 8) h.err_tail.erase(h.err_tail.begin());
  }

  /// After the session ended during preflight: its exit code and stderr, as one line.
  std::string why_ended(Host& h) {
    std::string line;
    while (h.err->next(line, 2000) == LineReader::Result::line) note_stderr(h, trim(line));
    int status = 0;
    for (int i = 0; i < 300 && waitpid(h.proc.pid, &status, WNOHANG) == 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    h.reaped = true;
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const std::string last = h.err_tail.empty() ? "no message" : h.err_tail.back();
    if (code == 255) return who(h) + ": unreachable over ssh: " + last;
    if (code == 126 || code == 127) return who(h) + ": cannot run plexus there: " + last;
    return who(h) + ": " + last + " (exit code " + std::to_string(code) + ")";
  }

  /// The next stdout line of a host during preflight, its stderr read meanwhile.
  bool next_line(Host& h, std::string& line, int64_t deadline_ns) {
    for (;;) {
      std::string e;
      while (h.err->poll_line(e) == LineReader::Result::line) note_stderr(h, trim(e));
      const int64_t left_ms = (deadline_ns - monotonic_ns()) / 1'000'000;
      if (left_ms <= 0) return false;
      const auto r = h.out->next(line, static_cast<int>(std::min<int64_t>(left_ms, 100)));
      if (r == LineReader::Result::line) return true;
      if (r == LineReader::Result::closed) return false;
    }
  }

  void fail_preflight(const std::string& what) {
    close_all_and_reap(5.0);
    throw InputError(what);
  }

  void close_all_and_reap(double grace_s) {
    for (auto& h : hosts)
      if (h->proc.in >= 0) ::close(h->proc.in), h->proc.in = -1;
    const int64_t end = monotonic_ns() + static_cast<int64_t>(grace_s * 1e9);
    for (auto& h : hosts) {
      if (h->reaped || h->proc.pid <= 0) continue;
      int status = 0;
      while (monotonic_ns() < end && waitpid(h->proc.pid, &status, WNOHANG) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      if (waitpid(h->proc.pid, &status, WNOHANG) == 0) {
        ::kill(-h->proc.pid, SIGKILL);
        waitpid(h->proc.pid, &status, 0);
      }
      h->reaped = true;
    }
    for (auto& h : hosts) close_pipes(h->proc);
  }

  void lost(Host& h, const std::string& why) {
    std::lock_guard lk(mu);
    h.state = "lost";
    if (failure.empty() && !stopping) {
      failure = why;
      if (stop_flag) *stop_flag = true;
    }
  }

  void route(Host& h, const std::string& raw) {
    // A remote LogRelay line is "<process padded> | <text>"; anything else is the remote launcher's own.
    const std::string line = trim(raw);
    const auto bar = line.find(" | ");
    std::string process = "launch", text = line;
    if (bar != std::string::npos) {
      const std::string name = trim(line.substr(0, bar));
      if (std::find(h.processes.begin(), h.processes.end(), name) != h.processes.end())
        process = name, text = line.substr(bar + 3);
    }
    note_stderr(h, line);
    std::lock_guard lk(mu);
    auto it = h.relay_fd.find(process);
    if (it != h.relay_fd.end()) write_line(it->second, text);
  }

  void monitor(Host& h) {
    bool out_open = true, err_open = true;
    int64_t next_alive = monotonic_ns();
    while (out_open || err_open) {
      std::string line;
      if (err_open) {
        LineReader::Result r;
        while ((r = h.err->next(line, out_open ? 0 : 100)) == LineReader::Result::line) route(h, line);
        if (r == LineReader::Result::closed) err_open = false;
      }
      if (out_open) {
        const auto r = h.out->next(line, 50);
        if (r == LineReader::Result::closed) out_open = false;
        if (r == LineReader::Result::line && line.rfind("status ", 0) == 0) {
          std::istringstream in(line.substr(7));
          int running = 0, expected = 0;
          in >> running >> expected;
          std::lock_guard lk(mu);
          h.running = running, h.expected = expected, h.state = "running";
          h.heard_ns = monotonic_ns();
          if (h.alive_sent_ns) h.rtt_ns = h.heard_ns - h.alive_sent_ns;
        }
      }
      const int64_t now = monotonic_ns();
      if (!stopping && out_open && now >= next_alive) {
        next_alive = now + static_cast<int64_t>(kAliveIntervalS * 1e9);
        int fd;
        {
          std::lock_guard lk(mu);
          fd = h.proc.in;
          h.alive_sent_ns = now;
        }
        if (fd >= 0) write_line(fd, "alive");
      }
      int64_t heard;
      {
        std::lock_guard lk(mu);
        heard = h.heard_ns;
      }
      if (!stopping && heard && now - heard > static_cast<int64_t>(kSilenceLimitS * 1e9)) {
        lost(h, who(h) + " lost: no answer for " + std::to_string(static_cast<int>(kSilenceLimitS)) + " s");
        ::kill(-h.proc.pid, SIGTERM);  // ends the session: the share stops when it notices
      }
    }
    int status = 0;
    waitpid(h.proc.pid, &status, 0);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const std::string last = h.err_tail.empty() ? "" : ": " + h.err_tail.back();
    if (code == 0) {
      std::lock_guard lk(mu);
      if (h.state != "lost") h.state = "done";
    } else if (WIFSIGNALED(status)) {
      lost(h, who(h) + " lost: its ssh session was killed (signal " + std::to_string(WTERMSIG(status)) + ")");
    } else if (code == 255) {
      lost(h, who(h) + " lost: the ssh session ended" + last);
    } else {
      lost(h, who(h) + ": its share failed (exit code " + std::to_string(code) + ")" + last);
    }
    std::lock_guard lk(mu);
    h.exit_code = code;
    h.reaped = true;
    for (auto& [name, fd] : h.relay_fd) ::close(fd);
    h.relay_fd.clear();
    reaped_cv.notify_all();
  }
};

RemoteShares::RemoteShares(const scenario::Scenario& sc, const std::string& local, std::vector<std::string> hosts,
                           RemoteShareOptions options)
    : impl_(std::make_unique<Impl>(sc, local, std::move(options))) {
  std::signal(SIGPIPE, SIG_IGN);  // a closed session is EPIPE on write, not the launcher's death
  for (const auto& name : hosts) {
    auto h = std::make_unique<Impl::Host>();
    h->name = name;
    h->destination = sc.host_access.at(name).ssh;
    h->address = sc.host_address.at(name);
    for (const auto& p : plan(sc, name)) h->processes.push_back(p.service());
    impl_->hosts.push_back(std::move(h));
  }
}

RemoteShares::~RemoteShares() { stop(); }

void RemoteShares::preflight(const std::string& version, const std::string& digest) {
  auto& m = *impl_;
  // Every session at once: the connections proceed in parallel.
  for (auto& h : m.hosts) {
    const auto cmd = remote_launch_command(m.sc.host_access.at(h->name), m.o.local_plexus);
    try {
      h->proc = spawn_piped(m.o.ssh_program, ssh_arguments(m.o.ssh, h->destination, cmd));
    } catch (const std::exception& e) {
      m.fail_preflight(m.who(*h) + ": " + e.what() + " (is openssh-client installed?)");
    }
    h->out = std::make_unique<LineReader>(h->proc.out);
    h->err = std::make_unique<LineReader>(h->proc.err);
  }
  const int64_t deadline = monotonic_ns() + static_cast<int64_t>(m.o.answer_timeout_s * 1e9);
  std::string line;
  // 1. Reachable, and the same plexus version.
  for (auto& h : m.hosts) {
    if (!m.next_line(*h, line, deadline)) {
      if (monotonic_ns() >= deadline)
        m.fail_preflight(m.who(*h) + ": no answer within " + std::to_string(static_cast<int>(m.o.answer_timeout_s)) +
                         " s");
      m.fail_preflight(m.why_ended(*h));
    }
    int protocol = 0;
    std::string theirs;
    if (!parse_hello(line, protocol, theirs))
      m.fail_preflight(m.who(*h) + ": the program there is not a plexus launcher (it said '" + line.substr(0, 60) +
                       "')");
    if (theirs != version || protocol != kRemoteProtocol)
      m.fail_preflight(m.who(*h) + ": plexus " + theirs + " there, " + version +
                       " here: install the same build on every host");
  }
  // 2. The scenario, sent rather than assumed present; the host loads it and checks its address.
  for (auto& h : m.hosts) {
    RemoteRequest r = m.o.request;
    r.host = h->name;
    r.out = m.o.out.empty() ? "" : m.o.out + "-" + h->name;
    r.clock_injection_ns = m.o.clock_injection_ns.count(h->name) ? m.o.clock_injection_ns.at(h->name) : 0;
    if (!write_line(h->proc.in, r.to_line())) m.fail_preflight(m.why_ended(*h));
  }
  for (auto& h : m.hosts) {
    RemoteReady ready;
    if (!m.next_line(*h, line, deadline)) m.fail_preflight(m.why_ended(*h));
    if (!RemoteReady::from_line(line, ready))
      m.fail_preflight(m.who(*h) + ": unexpected answer '" + line.substr(0, 60) + "'");
    if (!ready.address_found)
      m.fail_preflight(m.who(*h) + ": address " + ready.address + " (hosts." + h->name +
                       ".address) is on none of its interfaces");
    if (ready.digest != digest)
      m.fail_preflight(m.who(*h) + ": the scenario resolves differently there (digest " + ready.digest + ", here " +
                       digest + "): check its QoS profiles (" + ready.qos_file + ") and the files the scenario names");
    h->ready_s = static_cast<double>(monotonic_ns() - m.t0) * 1e-9;
  }
  // 3. Clock offsets: ping-pong over the session, the minimum-delay sample (clock_offset.hpp).
  for (auto& h : m.hosts) {
    std::vector<ClockSample> samples;
    for (int i = 0; i < m.o.clock_samples; ++i) {
      ClockSample s;
      s.t1 = wall_time_ns();
      if (!write_line(h->proc.in, "ping " + std::to_string(i))) m.fail_preflight(m.why_ended(*h));
      if (!m.next_line(*h, line, deadline)) m.fail_preflight(m.why_ended(*h));
      s.t4 = wall_time_ns();
      std::istringstream in(line);
      std::string word;
      int n = -1;
      in >> word >> n >> s.t2 >> s.t3;
      if (word != "pong" || n != i) m.fail_preflight(m.who(*h) + ": unexpected answer '" + line.substr(0, 60) + "'");
      samples.push_back(s);
    }
    try {
      h->offset = estimate_offset(samples);
    } catch (const std::invalid_argument& e) {
      m.fail_preflight(m.who(*h) + ": clock offset: " + e.what());
    }
  }
}

const ClockOffset& RemoteShares::offset(const std::string& host) const {
  for (const auto& h : impl_->hosts)
    if (h->name == host) return h->offset;
  static const ClockOffset zero;
  return zero;  // the local host
}

void RemoteShares::check_offsets(double base_step_s, bool realtime, bool allow) const {
  const int64_t bound = offset_bound_ns(base_step_s);
  for (const auto& h : impl_->hosts) {
    std::fprintf(stderr, "plexus launch: clock of %s: %s\n", h->name.c_str(), describe(h->offset).c_str());
    if (!realtime || std::llabs(h->offset.offset_ns) <= bound) continue;
    char msg[320];
    std::snprintf(msg, sizeof msg,
                  "its clock is %+.3f ms from this one's, beyond the realtime bound of %.3f ms (a tenth of the %.3g ms "
                  "step): synchronise the clocks (NTP, PTP) or pass --allow-clock-offset",
                  static_cast<double>(h->offset.offset_ns) * 1e-6, static_cast<double>(bound) * 1e-6,
                  base_step_s * 1e3);
    if (!allow) {
      impl_->close_all_and_reap(5.0);
      throw InputError(impl_->who(*h) + ": " + msg);
    }
    std::fprintf(stderr, "plexus launch: warning: %s: %s (allowed)\n", impl_->who(*h).c_str(), msg);
  }
}

void RemoteShares::start(LogRelay& relay, int local_processes, std::atomic<bool>& stop) {
  auto& m = *impl_;
  m.stop_flag = &stop;
  m.local_expected = local_processes;
  for (auto& h : m.hosts) {
    {
      std::lock_guard lk(m.mu);
      for (const auto& p : h->processes) h->relay_fd[p] = relay.open(h->name + "/" + p);
      h->relay_fd["launch"] = relay.open(h->name + "/launch");
      h->heard_ns = monotonic_ns();
    }
    if (!write_line(h->proc.in, "go")) m.lost(*h, m.why_ended(*h));
  }
  for (auto& h : m.hosts) h->monitor = std::thread([&m, hp = h.get()] { m.monitor(*hp); });
}

std::string RemoteShares::health() const {
  auto& m = *impl_;
  std::vector<pid_t> sessions;
  for (const auto& h : m.hosts) sessions.push_back(h->proc.pid);
  std::string s = m.local + " " + std::to_string(running_children(sessions)) + "/" + std::to_string(m.local_expected);
  std::lock_guard lk(m.mu);
  for (const auto& h : m.hosts) {
    s += ", " + h->name + " ";
    if (h->state == "running") {
      char rtt[48] = "";
      if (h->rtt_ns >= 0) std::snprintf(rtt, sizeof rtt, " (%.1f ms)", static_cast<double>(h->rtt_ns) * 1e-6);
      s += std::to_string(h->running) + "/" + std::to_string(h->expected) + rtt;
    } else {
      s += h->state;
    }
  }
  return s;
}

std::string RemoteShares::failure() const {
  std::lock_guard lk(impl_->mu);
  return impl_->failure;
}

void RemoteShares::stop(double grace_s) {
  auto& m = *impl_;
  if (m.stopped) return;
  m.stopped = true;
  m.stopping = true;
  bool monitored = false;
  for (auto& h : m.hosts) monitored = monitored || h->monitor.joinable();
  if (!monitored) {  // never started (preflight failed or the run never began)
    m.close_all_and_reap(grace_s);
    return;
  }
  {
    std::lock_guard lk(m.mu);
    for (auto& h : m.hosts)
      if (h->proc.in >= 0) ::close(h->proc.in), h->proc.in = -1;  // end of file: the share stops
  }
  std::unique_lock lk(m.mu);
  const auto all_reaped = [&] {
    return std::all_of(m.hosts.begin(), m.hosts.end(),
                       [](const auto& h) { return h->reaped || !h->monitor.joinable(); });
  };
  if (!m.reaped_cv.wait_for(lk, std::chrono::duration<double>(grace_s), all_reaped)) {
    for (auto& h : m.hosts)
      if (!h->reaped) ::kill(-h->proc.pid, SIGKILL);
  }
  lk.unlock();
  for (auto& h : m.hosts)
    if (h->monitor.joinable()) h->monitor.join();
  for (auto& h : m.hosts) close_pipes(h->proc);
}

nlohmann::ordered_json RemoteShares::report() const {
  auto& m = *impl_;
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  std::lock_guard lk(m.mu);
  for (const auto& h : m.hosts)
    j[h->name] = {{"ssh", h->destination},
                  {"address", h->address},
                  {"ready_s", h->ready_s},
                  {"clock_offset_ms", static_cast<double>(h->offset.offset_ns) * 1e-6},
                  {"clock_uncertainty_ms", static_cast<double>(h->offset.uncertainty_ns) * 1e-6},
                  {"clock_round_trip_ms", static_cast<double>(h->offset.delay_ns) * 1e-6},
                  {"state", h->state},
                  {"exit_code", h->exit_code}};
  return j;
}

std::unique_ptr<RemoteShares> preflight_hosts(const scenario::Scenario& sc, const std::string& local_host,
                                              const std::string& local_address, const std::vector<std::string>& hosts,
                                              const RemoteLaunchArgs& a, const std::string& version,
                                              const std::string& digest) {
  if (!address_on_interface(local_address))
    throw InputError("host " + local_host + " (this machine): address " + local_address + " (hosts." + local_host +
                     ".address) is on none of its interfaces");
  if (!a.ssh_config.empty() && !std::filesystem::is_regular_file(a.ssh_config))
    throw InputError("--ssh-config " + a.ssh_config + ": no such file");
  RemoteShareOptions ro;
  ro.ssh.config_file = a.ssh_config;
  ro.local_plexus = bin_dir() + "/plexus";
  std::ifstream text(a.scenario_file, std::ios::binary);
  ro.request.scenario_text.assign(std::istreambuf_iterator<char>(text), {});
  ro.request.scenario_origin = a.scenario_file;
  ro.request.sets = a.sets, ro.request.vendors = a.vendors, ro.request.externals = a.externals;
  ro.request.dds = a.dds, ro.request.qos_file = a.qos_file, ro.request.domain = a.domain,
  ro.request.timeout = a.timeout;
  ro.out = a.out;
  for (const auto& inj : a.clock_injections) {
    const auto eq = inj.find('=');
    char* end = nullptr;
    const double s = eq == std::string::npos ? 0.0 : std::strtod(inj.c_str() + eq + 1, &end);
    if (eq == std::string::npos || !end || *end || !std::isfinite(s) ||
        std::find(hosts.begin(), hosts.end(), inj.substr(0, eq)) == hosts.end())
      throw InputError("--inject-clock-offset " + inj + ": expected HOST=SECONDS with a host started over ssh");
    ro.clock_injection_ns[inj.substr(0, eq)] = std::llround(s * 1e9);
  }
  auto remotes = std::make_unique<RemoteShares>(sc, local_host, hosts, ro);
  remotes->preflight(version, digest);
  remotes->check_offsets(sc.step, sc.clock == scenario::ClockMode::realtime, a.allow_clock_offset);
  return remotes;
}

}  // namespace plexus::cli
