#include "realtime_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include <spdlog/spdlog.h>

#include "plexus/base/clock.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/scenario/step_executor.hpp"

namespace plexus::cli {
namespace {

double percentile_us(std::vector<int64_t> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return static_cast<double>(v[k]) * 1e-3;
}

}  // namespace

RealtimeResult run_realtime(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                            const std::vector<Process>& procs, double start_timeout_s, double ready_wait_s,
                            FaultClock& fault, StatusConsole& console, const std::atomic<bool>& stop,
                            const std::map<std::string, int64_t>& host_clock_offset_ns) {
  RealtimeResult res;
  scenario::StepExecutor wiring(sc, std::vector<bool>(sc.components.size(), false));
  const auto& signals = wiring.signals();
  // The signals the plants read from other processes: the commands.
  std::vector<bool> plants(sc.components.size(), false);
  for (std::size_t i = 0; i < sc.components.size(); ++i)
    plants[i] = sc.components[i].kind == scenario::ComponentKind::plant;
  const auto commands = scenario::StepExecutor(sc, plants).remote_inputs();
  // A command's latency starts at its robot's sensor sample, stamped on the plant's host.
  std::vector<int64_t> origin_offset(signals.size(), 0);
  std::vector<bool> corrected(signals.size(), false);
  for (const auto& c : sc.components) {
    const auto off = host_clock_offset_ns.find(c.host);
    if (!plants[&c - sc.components.data()] || off == host_clock_offset_ns.end()) continue;
    for (const auto& in : c.component->inputs())
      for (std::size_t s = 0; s < signals.size(); ++s)
        if (signals[s].name == in->signal()) origin_offset[s] = off->second, corrected[s] = true;
  }

  rt::QosProfile any = profiles.get("sensor");  // best effort, volatile: matches every producer
  any.depth = 256;
  std::vector<std::unique_ptr<distributed::WireSubscriber>> subs;
  for (const auto& spec : signals)
    subs.push_back(std::make_unique<distributed::WireSubscriber>(participant, spec, distributed::step_ns(sc), any));
  std::vector<rt::Subscriber<msg::Heartbeat>> beats;
  for (const auto& p : procs) beats.push_back(participant.subscriber<msg::Heartbeat>(distributed::health_topic(p.service()), profiles.get("health")));
  auto go = participant.publisher<msg::ClockStep>(distributed::kClockTopic, profiles.get("lockstep"));

  res.log.base_step = sc.step;
  res.log.steps = sc.steps;
  res.log.signals.resize(signals.size());
  for (std::size_t s = 0; s < signals.size(); ++s) res.log.signals[s].spec = signals[s];
  std::vector<std::vector<int64_t>> latency(signals.size());
  std::vector<msg::Heartbeat> last(procs.size());
  std::vector<bool> seen(procs.size(), false);

  double heartbeat_after_s = -1;  // first heartbeat from a new pid (a restarted process) after the kill
  std::vector<uint32_t> pid_of(procs.size(), 0);
  auto drain_beats = [&] {
    for (std::size_t i = 0; i < beats.size(); ++i) {
      if (!beats[i].take_latest(last[i])) continue;
      seen[i] = true;
      // A heartbeat from another pid than before: the process was started again.
      if (pid_of[i] && last[i].pid() != pid_of[i] && fault.killed_ns.load() && heartbeat_after_s < 0)
        heartbeat_after_s = static_cast<double>(monotonic_ns() - fault.killed_ns.load()) * 1e-9;
      pid_of[i] = last[i].pid();
    }
  };
  // Every process reports first (start_timeout_s). Then the run starts when every process
  // is ready: a service waiting for the start reports CONFIGURING until each of its inputs
  // from other processes has matched a writer (distributed/realtime.cpp), which on a lossy
  // link takes seconds; a loop started before would hold its safe output until then. Past
  // ready_wait_s the run starts anyway, and says which processes were still matching.
  const int64_t give_up = monotonic_ns() + static_cast<int64_t>(start_timeout_s * 1e9);
  int64_t ready_by = 0;  // set once every process has reported
  for (;;) {
    drain_beats();
    std::string silent, matching;
    for (std::size_t i = 0; i < procs.size(); ++i) {
      if (!seen[i]) silent += (silent.empty() ? "" : ", ") + procs[i].service();
      else if (last[i].state() == msg::SERVICE_CONFIGURING) matching += (matching.empty() ? "" : ", ") + procs[i].service();
    }
    const int64_t now = monotonic_ns();
    if (silent.empty() && ready_by == 0) ready_by = now + static_cast<int64_t>(ready_wait_s * 1e9);
    if (silent.empty() && matching.empty()) break;
    if (silent.empty() && now > ready_by) {
      spdlog::warn("realtime: starting with inputs not yet matched to their writers after {} s: {} (they hold "
                   "their safe output until the inputs arrive)",
                   scenario::format_number(ready_wait_s), matching);
      break;
    }
    if (stop) throw distributed::LockstepError("realtime: stopped before the start");
    if (!silent.empty() && now > give_up) throw distributed::LockstepError("realtime: no heartbeat from " + silent);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  res.all_running_ns = monotonic_ns();
  msg::ClockStep start;
  start.step_index(0);
  // The run's start on the wall clock, far enough ahead that every host has the start signal
  // before tick 0; each host ticks on the grid it defines, a restarted one at the current tick.
  constexpr int64_t kStartLeadNs = 200'000'000;
  start.sim_time_ns(wall_time_ns() + kStartLeadNs);
  for (auto& s : subs) s->wire().set_epoch(start.sim_time_ns());  // data times: wall clock on the run's grid
  go.publish(start);
  const int64_t t0 = monotonic_ns() + kStartLeadNs;
  fault.run_start_ns = t0;
  double safe_after_s = -1;  // first all-zero command after an injected kill
  std::vector<double> safe_after_by_command(signals.size(), -1.0);  // the same, per command signal
  const int64_t end = t0 + static_cast<int64_t>((sc.duration + 2.0) * 1e9);
  scenario::SignalSample sample;
  std::size_t bad_field = 0;
  // The live status line, once a second: loop rates, deadline misses, command latency.
  // Loop rates come from consecutive heartbeats (loop count over their publish times), so a
  // heartbeat that has not arrived yet this second does not read as a stopped loop.
  std::vector<uint64_t> loops_before(procs.size(), 0), misses_before(procs.size(), 0);
  std::vector<int64_t> beat_before(procs.size(), 0);
  std::vector<double> rate_of(procs.size(), 0.0);
  std::vector<std::size_t> latency_before(signals.size(), 0);
  int64_t status_at = t0;
  auto show_status = [&](int64_t now) {
    const double dt = static_cast<double>(now - status_at) * 1e-9;
    double min_rate = 1e18;
    std::string slowest;
    uint64_t misses = 0;
    for (std::size_t i = 0; i < procs.size(); ++i) {
      const int64_t beat = last[i].header().publish_time_ns();
      if (beat > beat_before[i]) {
        if (beat_before[i] > 0 && last[i].loop_count() >= loops_before[i])
          rate_of[i] = static_cast<double>(last[i].loop_count() - loops_before[i]) /
                       (static_cast<double>(beat - beat_before[i]) * 1e-9);
        beat_before[i] = beat;
        loops_before[i] = last[i].loop_count();
      }
      if (rate_of[i] > 0 && rate_of[i] < min_rate) min_rate = rate_of[i], slowest = procs[i].service();  // 0: unknown yet
      const uint64_t miss = last[i].overruns() + last[i].stale_inputs();
      misses += miss - std::min(miss, misses_before[i]);
      misses_before[i] = miss;
    }
    std::string lat;
    for (std::size_t s : commands) {
      auto& l = latency[s];
      std::vector<int64_t> window(l.begin() + static_cast<std::ptrdiff_t>(latency_before[s]), l.end());
      latency_before[s] = l.size();
      if (window.empty()) continue;
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s%s %.1f/%.1f", lat.empty() ? "" : ", ", signals[s].name.c_str(),
                    percentile_us(window, 0.5) * 1e-3, percentile_us(window, 0.99) * 1e-3);
      lat += buf;
    }
    char line[512];
    char loop[160] = "slowest loop -";
    if (!slowest.empty()) std::snprintf(loop, sizeof loop, "slowest loop %.0f Hz (%s)", min_rate, slowest.c_str());
    std::snprintf(line, sizeof line, "t %5.1f/%.0f s | %s | deadline misses %llu/s | sensor->cmd p50/p99 ms: %s",
                  static_cast<double>(now - t0) * 1e-9, sc.duration, loop,
                  static_cast<unsigned long long>(static_cast<double>(misses) / dt), lat.c_str());
    console.status(line);
    status_at = now;
  };
  while (monotonic_ns() < end && !stop) {
    if (monotonic_ns() - status_at >= 1'000'000'000) show_status(monotonic_ns());
    bool any_data = false;
    for (std::size_t s = 0; s < subs.size(); ++s) {
      while (const void* m = subs[s]->take()) {
        any_data = true;
        const int64_t now = wall_time_ns();
        if (subs[s]->wire().decode(m, sample, bad_field) != distributed::Rejection::none) continue;
        // A producer started before the run (a native plant, a bridge) or running past its end
        // has samples off the run's steps; a late or repeated step is not a new sample.
        auto& trace = res.log.signals[s];
        if (sample.step < 0 || sample.step > sc.steps || (!trace.steps.empty() && sample.step <= trace.steps.back()))
          continue;
        res.log.record(s, sample);
        const int64_t origin = subs[s]->header().origin_time_ns();
        if (origin > distributed::kNoMeasurementOrigin) latency[s].push_back(now - origin + origin_offset[s]);
        const int64_t killed = fault.killed_ns.load();
        const auto width = static_cast<std::ptrdiff_t>(signals[s].fields.size());
        if (killed && safe_after_by_command[s] < 0 && std::find(commands.begin(), commands.end(), s) != commands.end() &&
            std::all_of(sample.values.begin(), sample.values.begin() + width, [](double v) { return v == 0.0; })) {
          safe_after_by_command[s] = static_cast<double>(monotonic_ns() - killed) * 1e-9;
          if (safe_after_s < 0) safe_after_s = safe_after_by_command[s];
        }
      }
    }
    drain_beats();
    bool all_done = true;
    for (const auto& hb : last) all_done = all_done && hb.state() == msg::SERVICE_DRAINING;
    if (all_done) break;
    if (!any_data) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  res.wall = static_cast<double>(monotonic_ns() - t0) * 1e-9;
  for (std::size_t i = 0; i < procs.size(); ++i) {
    const auto& hb = last[i];
    res.services[procs[i].service()] = {{"loop_count", hb.loop_count()},         {"overruns", hb.overruns()},
                                        {"stale_input_reads", hb.stale_inputs()}, {"late_input_reads", hb.late_inputs()},  {"rejected_inputs", hb.rejected_inputs()},
                                        {"jitter_p50_us", hb.jitter_p50_us()},
                                        {"jitter_p99_us", hb.jitter_p99_us()},     {"jitter_max_us", hb.jitter_max_us()},
                                        {"compute_p50_us", hb.compute_p50_us()},   {"compute_p99_us", hb.compute_p99_us()}};
  }
  if (fault.killed_ns.load()) {
    const auto seconds_or_null = [](double s) { return s >= 0 ? nlohmann::ordered_json(s) : nlohmann::ordered_json(); };
    const auto since_kill = [&](int64_t ns) { return ns ? static_cast<double>(ns - fault.killed_ns.load()) * 1e-9 : -1.0; };
    // The kill on the run's clock (the grid: step k at k base steps), for reading signals/.
    res.fault["killed_at_s"] = static_cast<double>(fault.killed_ns.load() - t0) * 1e-9;
    res.fault["safe_command_after_s"] = seconds_or_null(safe_after_s);
    nlohmann::ordered_json per_command = nlohmann::ordered_json::object();
    for (std::size_t s : commands) per_command[signals[s].name] = seconds_or_null(safe_after_by_command[s]);
    res.fault["safe_command_after_s_by_command"] = per_command;
    res.fault["respawned_after_s"] = seconds_or_null(since_kill(fault.respawned_ns.load()));
    res.fault["first_heartbeat_after_s"] = seconds_or_null(heartbeat_after_s);
    res.fault["input_deadline_periods"] = sc.input_deadline_periods;
  }
  for (std::size_t s : commands) {
    res.latency[signals[s].name] = {{"samples", latency[s].size()},
                                    {"p50_us", percentile_us(latency[s], 0.5)},
                                    {"p99_us", percentile_us(latency[s], 0.99)},
                                    {"max_us", percentile_us(latency[s], 1.0)}};
    if (corrected[s]) res.latency[signals[s].name]["clock_offset_corrected_us"] = static_cast<double>(origin_offset[s]) * 1e-3;
  }
  return res;
}

}  // namespace plexus::cli
