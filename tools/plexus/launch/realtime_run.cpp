#include "realtime_run.hpp"

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <spdlog/spdlog.h>

#include "monitor_view.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/scenario/step_executor.hpp"
#include "timing_budget.hpp"

namespace plexus::cli {
namespace {

std::vector<bool> plants_of(const scenario::Scenario& sc) {
  std::vector<bool> plants(sc.components.size(), false);
  for (std::size_t i = 0; i < sc.components.size(); ++i)
    plants[i] = sc.components[i].kind == scenario::ComponentKind::plant;
  return plants;
}

/// The page's status every quarter second; the latency it shows, over the last second.
constexpr int64_t kWebPeriodNs = 250'000'000;
constexpr std::size_t kPlotPointsPerStatus = 2000;

/// The host a process runs on: its components' (the first host when they name none).
std::string host_of(const scenario::Scenario& sc, const Process& p) {
  const std::string first = sc.hosts.empty() ? "local" : sc.hosts.front();
  if (p.components.empty() || sc.components[p.components.front()].host.empty()) return first;
  return sc.components[p.components.front()].host;
}

/// One realtime run as the launcher sees it: every signal, every process's heartbeat, the
/// start signal, the live status line, and what it all adds up to (run_realtime).
class RealtimeMonitor {
 public:
  RealtimeMonitor(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                  const std::vector<Process>& procs, FaultClock& fault, StatusConsole& console,
                  const std::map<std::string, int64_t>& host_clock_offset_ns, BudgetCheck* budget, WebMonitor* web);
  /// Every process reports, then is ready (or ready_wait_s passes); throws LockstepError.
  void wait_for_start(double start_timeout_s, double ready_wait_s, const std::atomic<bool>& stop);
  /// Publishes the start signal; returns the monotonic time of tick 0.
  int64_t start();
  /// Records until the duration has passed, every process is draining, or `stop`.
  void record(const std::atomic<bool>& stop);
  RealtimeResult result();
  /// --monitor: the page's status ("starting", "running", "done"), at most every kWebPeriodNs
  /// unless `now_anyway`.
  void publish_web(int64_t now, const char* phase, bool now_anyway = false);

 private:
  void drain_beats();
  bool take_samples();  // true when any sample arrived
  void note_safe_command(std::size_t s, const scenario::SignalSample& sample);
  void show_status(int64_t now);
  std::string latency_status();
  nlohmann::ordered_json fault_record() const;

  scenario::Scenario& sc_;
  const std::vector<Process>& procs_;
  BudgetCheck* budget_;  // the loops' timing budgets (null: not checked)
  FaultClock& fault_;
  StatusConsole& console_;
  scenario::StepExecutor wiring_;
  const std::vector<scenario::SignalSpec>& signals_;
  std::vector<std::size_t> commands_;   // the signals the plants read from other processes
  std::vector<int64_t> origin_offset_;  // by signal: the clock offset of its origin's host
  std::vector<bool> corrected_;         // by signal: origin_offset_ applies
  std::vector<std::unique_ptr<distributed::WireSubscriber>> subs_;
  std::vector<rt::Subscriber<msg::Heartbeat>> beats_;
  std::optional<rt::Publisher<msg::ClockStep>> go_;  // the start signal
  RealtimeResult res_;
  std::vector<std::vector<int64_t>> latency_;  // by signal: sensor-to-arrival latencies, ns
  std::vector<msg::Heartbeat> last_;
  std::vector<bool> seen_;
  std::vector<uint32_t> pid_of_;
  double heartbeat_after_s_ = -1;  // first heartbeat from a new pid (a restarted process) after the kill
  int64_t t0_ = 0;
  double safe_after_s_ = -1;                   // first all-zero command after an injected kill
  std::vector<double> safe_after_by_command_;  // the same, per command signal
  scenario::SignalSample sample_;
  std::size_t bad_field_ = 0;
  // The live status line. Loop rates come from consecutive heartbeats (loop count over their
  // publish times), so a heartbeat that has not arrived yet this second does not read as a
  // stopped loop.
  std::vector<uint64_t> loops_before_, misses_before_;
  std::vector<int64_t> beat_before_;
  std::vector<double> rate_of_;
  std::vector<std::size_t> latency_before_;
  int64_t status_at_ = 0;
  // --monitor (web_monitor.hpp): the page's view of each process, the plotted field, and the
  // latency of the last status line's second.
  WebMonitor* web_;
  std::map<std::string, int64_t> host_offsets_;
  std::vector<ProcessView> views_;    // by process: name and host set once, the rest per status
  std::vector<bool> local_;           // by process: on this host, so its pid can be checked
  std::vector<int64_t> received_ns_;  // by process: monotonic arrival of its last heartbeat
  std::vector<int> restarts_;         // by process: heartbeats from a new pid
  PlotFeed plot_;
  nlohmann::json latency_json_ = nlohmann::json::object();  // latency_status()'s, per command
  int64_t web_at_ = 0;
};

RealtimeMonitor::RealtimeMonitor(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                                 const std::vector<Process>& procs, FaultClock& fault, StatusConsole& console,
                                 const std::map<std::string, int64_t>& host_clock_offset_ns, BudgetCheck* budget,
                                 WebMonitor* web)
    : sc_(sc),
      procs_(procs),
      budget_(budget),
      fault_(fault),
      console_(console),
      wiring_(sc, std::vector<bool>(sc.components.size(), false)),
      signals_(wiring_.signals()),
      commands_(scenario::StepExecutor(sc, plants_of(sc)).remote_inputs()),
      origin_offset_(signals_.size(), 0),
      corrected_(signals_.size(), false),
      latency_(signals_.size()),
      last_(procs.size()),
      seen_(procs.size(), false),
      pid_of_(procs.size(), 0),
      safe_after_by_command_(signals_.size(), -1.0),
      loops_before_(procs.size(), 0),
      misses_before_(procs.size(), 0),
      beat_before_(procs.size(), 0),
      rate_of_(procs.size(), 0.0),
      latency_before_(signals_.size(), 0),
      web_(web),
      host_offsets_(host_clock_offset_ns),
      views_(procs.size()),
      local_(procs.size(), false),
      received_ns_(procs.size(), 0),
      restarts_(procs.size(), 0) {
  const std::string here = sc.hosts.empty() ? "local" : sc.hosts.front();  // the clock's host
  for (std::size_t i = 0; i < procs.size(); ++i) {
    views_[i].name = procs[i].service();
    views_[i].host = host_of(sc, procs[i]);
    local_[i] = views_[i].host == here;
  }
  for (const auto& spec : signals_)  // plotted until a page asks for another field
    if (!spec.fields.empty()) {
      plot_.select(spec.name, spec.fields.front());
      break;
    }
  // A command's latency starts at its robot's sensor sample, stamped on the plant's host.
  for (const auto& c : sc.components) {
    const auto off = host_clock_offset_ns.find(c.host);
    if (c.kind != scenario::ComponentKind::plant || off == host_clock_offset_ns.end()) continue;
    for (const auto& in : c.component->inputs())
      for (std::size_t s = 0; s < signals_.size(); ++s)
        if (signals_[s].name == in->signal()) origin_offset_[s] = off->second, corrected_[s] = true;
  }
  rt::QosProfile any = profiles.get("sensor");  // best effort, volatile: matches every producer
  any.depth = 256;
  if (budget_) {  // a sample's publish time is its producer's clock
    std::map<std::string, int64_t> publish_offset;
    for (const auto& spec : signals_)
      for (const auto& c : sc.components)
        if (c.component->name() == spec.producer)
          if (const auto off = host_clock_offset_ns.find(c.host); off != host_clock_offset_ns.end())
            publish_offset[spec.name] = off->second;
    budget_->bind(participant, signals_, distributed::step_ns(sc), any, publish_offset);
  }
  for (const auto& spec : signals_)
    subs_.push_back(std::make_unique<distributed::WireSubscriber>(participant, spec, distributed::step_ns(sc), any));
  for (const auto& p : procs)
    beats_.push_back(
        participant.subscriber<msg::Heartbeat>(distributed::health_topic(p.service()), profiles.get("health")));
  go_.emplace(participant.publisher<msg::ClockStep>(distributed::kClockTopic, profiles.get("lockstep")));
  res_.log.base_step = sc.step;
  res_.log.steps = sc.steps;
  res_.log.signals.resize(signals_.size());
  for (std::size_t s = 0; s < signals_.size(); ++s) res_.log.signals[s].spec = signals_[s];
}

void RealtimeMonitor::drain_beats() {
  for (std::size_t i = 0; i < beats_.size(); ++i) {
    if (!beats_[i].take_latest(last_[i])) continue;
    seen_[i] = true;
    received_ns_[i] = monotonic_ns();
    // A heartbeat from another pid than before: the process was started again.
    if (pid_of_[i] && last_[i].pid() != pid_of_[i]) {
      ++restarts_[i];
      if (fault_.killed_ns.load() && heartbeat_after_s_ < 0)
        heartbeat_after_s_ = static_cast<double>(monotonic_ns() - fault_.killed_ns.load()) * 1e-9;
      beat_before_[i] = 0;  // its loop count starts again: its rate is not known until its next heartbeat
      rate_of_[i] = 0;
    }
    pid_of_[i] = last_[i].pid();
    // Its loop rate: loops over publish time since its previous heartbeat.
    const int64_t beat = last_[i].header().publish_time_ns();
    if (beat > beat_before_[i]) {
      if (beat_before_[i] > 0 && last_[i].loop_count() >= loops_before_[i])
        rate_of_[i] = static_cast<double>(last_[i].loop_count() - loops_before_[i]) /
                      (static_cast<double>(beat - beat_before_[i]) * 1e-9);
      beat_before_[i] = beat;
      loops_before_[i] = last_[i].loop_count();
    }
  }
}

// Every process reports first (start_timeout_s). Then the run starts when every process
// is ready: a service waiting for the start reports CONFIGURING until each of its inputs
// from other processes has matched a writer (distributed/realtime.cpp), which on a lossy
// link takes seconds; a loop started before would hold its safe output until then. Past
// ready_wait_s the run starts anyway, and says which processes were still matching.
void RealtimeMonitor::wait_for_start(double start_timeout_s, double ready_wait_s, const std::atomic<bool>& stop) {
  const int64_t give_up = monotonic_ns() + static_cast<int64_t>(start_timeout_s * 1e9);
  int64_t ready_by = 0;  // set once every process has reported
  for (;;) {
    drain_beats();
    std::string silent, matching;
    for (std::size_t i = 0; i < procs_.size(); ++i) {
      const std::string& name = procs_[i].service();
      if (!seen_[i])
        silent += (silent.empty() ? "" : ", ") + name;
      else if (last_[i].state() == msg::SERVICE_CONFIGURING)
        matching += (matching.empty() ? "" : ", ") + name;
    }
    const int64_t now = monotonic_ns();
    if (silent.empty() && ready_by == 0) ready_by = now + static_cast<int64_t>(ready_wait_s * 1e9);
    if (silent.empty() && matching.empty()) break;
    if (silent.empty() && now > ready_by) {
      spdlog::warn(
          "realtime: starting with inputs not yet matched to their writers after {} s: {} (they hold "
          "their safe output until the inputs arrive)",
          scenario::format_number(ready_wait_s), matching);
      break;
    }
    publish_web(now, "starting");
    if (stop) throw distributed::LockstepError("realtime: stopped before the start");
    if (!silent.empty() && now > give_up) throw distributed::LockstepError("realtime: no heartbeat from " + silent);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  res_.all_running_ns = monotonic_ns();
}

int64_t RealtimeMonitor::start() {
  msg::ClockStep start;
  start.step_index(0);
  // The run's start on the wall clock, far enough ahead that every host has the start signal
  // before tick 0; each host ticks on the grid it defines, a restarted one at the current tick.
  constexpr int64_t kStartLeadNs = 200'000'000;
  start.sim_time_ns(wall_time_ns() + kStartLeadNs);
  for (auto& s : subs_) s->wire().set_epoch(start.sim_time_ns());  // data times: wall clock on the run's grid
  go_->publish(start);
  t0_ = monotonic_ns() + kStartLeadNs;
  if (budget_) budget_->start(t0_);
  fault_.run_start_ns = t0_;
  status_at_ = t0_;
  return t0_;
}

void RealtimeMonitor::record(const std::atomic<bool>& stop) {
  const int64_t end = t0_ + static_cast<int64_t>((sc_.duration + 2.0) * 1e9);
  while (monotonic_ns() < end && !stop) {
    if (monotonic_ns() - status_at_ >= 1'000'000'000) show_status(monotonic_ns());
    publish_web(monotonic_ns(), "running");
    if (budget_) budget_->conclude(monotonic_ns());  // once, after the first second
    const bool any_data = take_samples();
    drain_beats();
    bool all_done = true;
    for (const auto& hb : last_) all_done = all_done && hb.state() == msg::SERVICE_DRAINING;
    if (all_done) break;
    if (!any_data) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  res_.wall = static_cast<double>(monotonic_ns() - t0_) * 1e-9;
  publish_web(monotonic_ns(), "done", true);
}

void RealtimeMonitor::publish_web(int64_t now, const char* phase, bool now_anyway) {
  if (!web_ || (!now_anyway && now - web_at_ < kWebPeriodNs)) return;
  web_at_ = now;
  for (std::size_t i = 0; i < views_.size(); ++i) {
    auto& v = views_[i];
    v.seen = seen_[i];
    v.beat = last_[i];
    v.age_s = seen_[i] ? static_cast<double>(now - received_ns_[i]) * 1e-9 : 0.0;
    v.rate_hz = rate_of_[i];
    v.restarts = restarts_[i];
    // On this host a killed process is known at once: its pid is gone (reaped by the supervisor).
    v.exited = local_[i] && seen_[i] && last_[i].pid() > 0 && ::kill(static_cast<pid_t>(last_[i].pid()), 0) != 0 &&
               errno == ESRCH;
  }
  std::string signal, field;
  bool reset = false;
  if (web_->plot_request(signal, field, reset)) {
    if (!signal.empty())
      plot_.select(signal, field);
    else if (reset)
      plot_.reset();
  }
  const double t = t0_ ? static_cast<double>(now - t0_) * 1e-9 : 0.0;
  web_->publish(status_json({phase, t, sc_.duration}, views_, host_offsets_, latency_json_,
                            plot_.next(res_.log, kPlotPointsPerStatus)));
}

bool RealtimeMonitor::take_samples() {
  bool any_data = false;
  for (std::size_t s = 0; s < subs_.size(); ++s) {
    while (const void* m = subs_[s]->take()) {
      any_data = true;
      const int64_t now = wall_time_ns();
      if (subs_[s]->wire().decode(m, sample_, bad_field_) != distributed::Rejection::none) continue;
      // A producer started before the run (a native plant, a bridge) or running past its end
      // has samples off the run's steps; a late or repeated step is not a new sample.
      auto& trace = res_.log.signals[s];
      if (sample_.step < 0 || sample_.step > sc_.steps || (!trace.steps.empty() && sample_.step <= trace.steps.back()))
        continue;
      res_.log.record(s, sample_);
      const int64_t origin = subs_[s]->header().origin_time_ns();
      if (origin > distributed::kNoMeasurementOrigin) latency_[s].push_back(now - origin + origin_offset_[s]);
      note_safe_command(s, sample_);
    }
  }
  return any_data;
}

/// After an injected kill: the first all-zero sample of each command (a controller's hold).
void RealtimeMonitor::note_safe_command(std::size_t s, const scenario::SignalSample& sample) {
  const int64_t killed = fault_.killed_ns.load();
  const auto width = static_cast<std::ptrdiff_t>(signals_[s].fields.size());
  if (killed && safe_after_by_command_[s] < 0 && std::find(commands_.begin(), commands_.end(), s) != commands_.end() &&
      std::all_of(sample.values.begin(), sample.values.begin() + width, [](double v) { return v == 0.0; })) {
    safe_after_by_command_[s] = static_cast<double>(monotonic_ns() - killed) * 1e-9;
    if (safe_after_s_ < 0) safe_after_s_ = safe_after_by_command_[s];
  }
}

// The live status line, once a second: loop rates, deadline misses, command latency.
void RealtimeMonitor::show_status(int64_t now) {
  const double dt = static_cast<double>(now - status_at_) * 1e-9;
  double min_rate = 1e18;
  std::string slowest;
  uint64_t misses = 0;
  for (std::size_t i = 0; i < procs_.size(); ++i) {
    if (rate_of_[i] > 0 && rate_of_[i] < min_rate)  // 0: unknown yet
      min_rate = rate_of_[i], slowest = procs_[i].service();
    const uint64_t miss = last_[i].overruns() + last_[i].stale_inputs();
    misses += miss - std::min(miss, misses_before_[i]);
    misses_before_[i] = miss;
  }
  const std::string lat = latency_status();
  char line[512];
  char loop[160] = "slowest loop -";
  if (!slowest.empty()) std::snprintf(loop, sizeof loop, "slowest loop %.0f Hz (%s)", min_rate, slowest.c_str());
  std::snprintf(line, sizeof line, "t %5.1f/%.0f s | %s | deadline misses %llu/s | sensor->cmd p50/p99 ms: %s",
                static_cast<double>(now - t0_) * 1e-9, sc_.duration, loop,
                static_cast<unsigned long long>(static_cast<double>(misses) / dt), lat.c_str());
  console_.status(line);
  status_at_ = now;
}

/// Each command's sensor-to-command latency since the last status line: "r1/cmd 1.2/3.4, ...";
/// the same figures, as JSON, for the page (latency_json_).
std::string RealtimeMonitor::latency_status() {
  std::string lat;
  for (std::size_t s : commands_) {
    auto& l = latency_[s];
    std::vector<int64_t> window(l.begin() + static_cast<std::ptrdiff_t>(latency_before_[s]), l.end());
    latency_before_[s] = l.size();
    if (window.empty()) continue;
    const double p50_ms = percentile_us(window, 0.5) * 1e-3, p99_ms = percentile_us(window, 0.99) * 1e-3;
    latency_json_[signals_[s].name] = {{"p50_ms", p50_ms}, {"p99_ms", p99_ms}};
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%s %.1f/%.1f", lat.empty() ? "" : ", ", signals_[s].name.c_str(), p50_ms, p99_ms);
    lat += buf;
  }
  return lat;
}

nlohmann::ordered_json RealtimeMonitor::fault_record() const {
  const auto seconds_or_null = [](double s) { return s >= 0 ? nlohmann::ordered_json(s) : nlohmann::ordered_json(); };
  const int64_t killed = fault_.killed_ns.load();
  const int64_t respawned = fault_.respawned_ns.load();
  nlohmann::ordered_json fault = nlohmann::ordered_json::object();
  // The kill on the run's clock (the grid: step k at k base steps), for reading signals/.
  fault["killed_at_s"] = static_cast<double>(killed - t0_) * 1e-9;
  fault["safe_command_after_s"] = seconds_or_null(safe_after_s_);
  nlohmann::ordered_json per_command = nlohmann::ordered_json::object();
  for (std::size_t s : commands_) per_command[signals_[s].name] = seconds_or_null(safe_after_by_command_[s]);
  fault["safe_command_after_s_by_command"] = per_command;
  fault["respawned_after_s"] = seconds_or_null(respawned ? static_cast<double>(respawned - killed) * 1e-9 : -1.0);
  fault["first_heartbeat_after_s"] = seconds_or_null(heartbeat_after_s_);
  fault["input_deadline_periods"] = sc_.input_deadline_periods;
  return fault;
}

RealtimeResult RealtimeMonitor::result() {
  for (std::size_t i = 0; i < procs_.size(); ++i) {
    const auto& hb = last_[i];
    res_.services[procs_[i].service()] = {
        {"loop_count", hb.loop_count()},           {"overruns", hb.overruns()},
        {"stale_input_reads", hb.stale_inputs()},  {"late_input_reads", hb.late_inputs()},
        {"rejected_inputs", hb.rejected_inputs()}, {"jitter_p50_us", hb.jitter_p50_us()},
        {"jitter_p99_us", hb.jitter_p99_us()},     {"jitter_max_us", hb.jitter_max_us()},
        {"compute_p50_us", hb.compute_p50_us()},   {"compute_p99_us", hb.compute_p99_us()}};
  }
  if (fault_.killed_ns.load()) res_.fault = fault_record();
  if (budget_) res_.loops = budget_->record();
  for (std::size_t s : commands_) {
    res_.latency[signals_[s].name] = {{"samples", latency_[s].size()},
                                      {"p50_us", percentile_us(latency_[s], 0.5)},
                                      {"p99_us", percentile_us(latency_[s], 0.99)},
                                      {"max_us", percentile_us(latency_[s], 1.0)}};
    if (corrected_[s])
      res_.latency[signals_[s].name]["clock_offset_corrected_us"] = static_cast<double>(origin_offset_[s]) * 1e-3;
  }
  return std::move(res_);
}

}  // namespace

RealtimeResult run_realtime(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                            const std::vector<Process>& procs, double start_timeout_s, double ready_wait_s,
                            FaultClock& fault, StatusConsole& console, const std::atomic<bool>& stop,
                            const std::map<std::string, int64_t>& host_clock_offset_ns, BudgetCheck* budget,
                            WebMonitor* web) {
  RealtimeMonitor monitor(sc, participant, profiles, procs, fault, console, host_clock_offset_ns, budget, web);
  monitor.wait_for_start(start_timeout_s, ready_wait_s, stop);
  monitor.start();
  monitor.record(stop);
  return monitor.result();
}

}  // namespace plexus::cli
