// plexus launch SCENARIO [--dds fast|cyclone] [--vendor PROCESS=VENDOR ...] [--set k=v ...] [--json]
//
// Runs a scenario distributed over DDS in lockstep: the robots' plants and sensors in a
// plant_simulator process, each service in its own process (the service executable of its
// type: localisation_observer, motion_controller, ..., see service_catalog.hpp), and the
// lockstep clock in this process. Writes the same run folder and metrics as `plexus sim`
// (so the digests can be compared) and reports steps_per_s. Children never outlive it.
#include <signal.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "log_relay.hpp"
#include "status_console.hpp"
#include "command.hpp"
#include "run_result.hpp"
#include "signal_recorder.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/distributed/service_catalog.hpp"
#include "plexus/scenario/step_executor.hpp"
#include "plexus/scenario/evaluation.hpp"
#include "plexus/scenario/progress_bar.hpp"
#include "plexus/scenario/run_folder.hpp"

namespace plexus::cli {
namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

struct LaunchOptions {
  std::string scenario;
  std::vector<std::string> sets;
  std::vector<std::string> vendors;  // PROCESS=VENDOR
  std::vector<std::string> kills;    // PROCESS@SECONDS (fault injection, realtime)
  std::vector<std::string> externals;  // processes provided from outside (replay, hardware bridge)
  std::string dds, out, qos_file, host, record;
  int domain = -1;
  double timeout = 10.0;
  bool json = false, quiet = false, report = false;
};

/// One child process: a name, the executable and its selection argument.
struct Process {
  std::string name;
  std::string program;
  std::vector<std::string> select;
  std::string vendor;
  pid_t pid = 0;
  std::string restart = "never";  ///< realtime: never | on_failure | always (scenario `restart`)
  std::vector<std::string> args;  ///< as started, to restart it the same way
  int restarts = 0;

  /// The service name the process reports in its heartbeats and DDS participant.
  std::string service() const { return select.empty() ? program : program + " " + select.back(); }
};

double percentile_us(std::vector<int64_t> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return static_cast<double>(v[k]) * 1e-3;
}

/// Realtime mode: start every process together, record every signal with its latency from
/// the sensor sample that started its chain, collect heartbeats, stop after the duration.
struct RealtimeResult {
  scenario::RunLog log;
  nlohmann::ordered_json services = nlohmann::ordered_json::object();
  nlohmann::ordered_json latency = nlohmann::ordered_json::object();
  nlohmann::ordered_json fault = nlohmann::ordered_json::object();
  double wall = 0;
};

/// Fault injection state shared with the launcher's watcher thread.
struct FaultClock {
  std::atomic<int64_t> run_start_ns{0};  ///< monotonic time of the start signal (0: not started)
  std::atomic<int64_t> killed_ns{0};     ///< monotonic time of the injected kill (0: none yet)
};

RealtimeResult run_realtime(scenario::Scenario& sc, rt::Participant& participant, const rt::QosProfiles& profiles,
                            std::vector<Process>& procs, double start_timeout_s, FaultClock& fault,
                            StatusConsole& console) {
  RealtimeResult res;
  scenario::StepExecutor wiring(sc, std::vector<bool>(sc.components.size(), false));
  const auto& signals = wiring.signals();
  // The signals the plants read from other processes: the commands.
  std::vector<bool> plants(sc.components.size(), false);
  for (std::size_t i = 0; i < sc.components.size(); ++i)
    plants[i] = sc.components[i].kind == scenario::ComponentKind::plant;
  const auto commands = scenario::StepExecutor(sc, plants).remote_inputs();

  rt::QosProfile any = profiles.get("sensor");  // best effort, volatile: matches every producer
  any.depth = 256;
  std::vector<rt::Subscriber<msg::Signal>> subs;
  for (const auto& spec : signals) subs.push_back(participant.subscriber<msg::Signal>(distributed::signal_topic(spec.name), any));
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

  auto drain_beats = [&] {
    for (std::size_t i = 0; i < beats.size(); ++i)
      if (beats[i].take_latest(last[i])) seen[i] = true;
  };
  const int64_t give_up = monotonic_ns() + static_cast<int64_t>(start_timeout_s * 1e9);
  while (std::find(seen.begin(), seen.end(), false) != seen.end()) {
    drain_beats();
    if (g_stop || monotonic_ns() > give_up) {
      std::string missing;
      for (std::size_t i = 0; i < seen.size(); ++i)
        if (!seen[i]) missing += (missing.empty() ? "" : ", ") + procs[i].service();
      throw distributed::LockstepError("realtime: no heartbeat from " + missing);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  msg::ClockStep start;
  start.step_index(0);
  // The run's start on the wall clock, far enough ahead that every host has the start signal
  // before tick 0; each host ticks on the grid it defines, a restarted one at the current tick.
  constexpr int64_t kStartLeadNs = 200'000'000;
  start.sim_time_ns(wall_time_ns() + kStartLeadNs);
  go.publish(start);
  const int64_t t0 = monotonic_ns() + kStartLeadNs;
  fault.run_start_ns = t0;
  double safe_after_s = -1;  // first all-zero command after an injected kill
  const int64_t end = t0 + static_cast<int64_t>((sc.duration + 2.0) * 1e9);
  msg::Signal m;
  scenario::SignalSample sample;
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
  while (monotonic_ns() < end && !g_stop) {
    if (monotonic_ns() - status_at >= 1'000'000'000) show_status(monotonic_ns());
    bool any_data = false;
    for (std::size_t s = 0; s < subs.size(); ++s) {
      while (subs[s].take(m)) {
        any_data = true;
        const int64_t now = wall_time_ns();
        if (m.count() != signals[s].fields.size()) continue;
        sample.step = m.step_index();
        std::copy_n(m.field_values().begin(), m.count(), sample.values.begin());
        res.log.record(s, sample);
        if (m.header().origin_time_ns() > distributed::kNoMeasurementOrigin)
          latency[s].push_back(now - m.header().origin_time_ns());
        const int64_t killed = fault.killed_ns.load();
        if (killed && safe_after_s < 0 && std::find(commands.begin(), commands.end(), s) != commands.end() &&
            std::all_of(sample.values.begin(), sample.values.begin() + m.count(), [](double v) { return v == 0.0; }))
          safe_after_s = static_cast<double>(monotonic_ns() - killed) * 1e-9;
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
    res.fault["safe_command_after_s"] = safe_after_s >= 0 ? nlohmann::ordered_json(safe_after_s) : nlohmann::ordered_json();
    res.fault["input_deadline_periods"] = sc.input_deadline_periods;
  }
  for (std::size_t s : commands)
    res.latency[signals[s].name] = {{"samples", latency[s].size()},
                                    {"p50_us", percentile_us(latency[s], 0.5)},
                                    {"p99_us", percentile_us(latency[s], 0.99)},
                                    {"max_us", percentile_us(latency[s], 1.0)}};
  return res;
}

/// Services that share a `process` key must agree on where and how that process runs, and
/// the process name must not be taken by another service or the plant simulator.
void check_process_groups(const scenario::Scenario& sc) {
  std::map<std::string, const scenario::ScenarioComponent*> first_of;
  for (const auto& c : sc.components) {
    if (c.process.empty()) continue;
    const std::string key = c.where + ".process";
    if (c.process.rfind("plant_simulator", 0) == 0)
      throw InputError(key + ": '" + c.process + "' is the plant simulator's process name");
    for (const auto& other : sc.components)
      if (other.component->name() == c.process && other.process != c.process && other.kind != scenario::ComponentKind::plant &&
          other.kind != scenario::ComponentKind::sensor)
        throw InputError(key + ": '" + c.process + "' is the name of service " + other.where +
                         ", which runs in a process of its own");
    auto [it, first] = first_of.emplace(c.process, &c);
    if (first) continue;
    const auto& f = *it->second;
    auto clash = [&](const char* what, const std::string& mine, const std::string& theirs) {
      if (mine != theirs)
        throw InputError(key + ": services of process '" + c.process + "' must agree on `" + what + "` ('" + mine +
                         "' here, '" + theirs + "' at " + f.where + ")");
    };
    clash("host", c.host, f.host);
    clash("dds", c.dds, f.dds);
    clash("restart", c.restart, f.restart);
  }
}

/// The processes of a scenario: one plant_simulator per host for the robots on that host,
/// one process per service in the executable of its type, or one per `process` group (in the
/// executable of its services' type if they share one, else component_host). With `host`
/// set, only those assigned to it (components without a host run on the first host).
std::vector<Process> plan(const scenario::Scenario& sc, const std::string& host) {
  check_process_groups(sc);
  const std::string first = sc.hosts.empty() ? "" : sc.hosts.front();
  auto here = [&](const std::string& h) { return host.empty() || (h.empty() ? first : h) == host; };
  std::vector<Process> procs;
  std::map<std::string, std::string> robots_by_host;  // host -> "r1,r2"
  std::map<std::string, std::string> dds_by_host;     // host -> the robots' `dds` key
  for (const auto& c : sc.components) {
    if (!here(c.host)) continue;
    if (c.kind == scenario::ComponentKind::plant) {
      const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
      auto& list = robots_by_host[c.host];
      list += (list.empty() ? "" : ",") + robot;
      auto [it, first_robot] = dds_by_host.emplace(c.host, c.dds);
      if (!first_robot && it->second != c.dds)
        throw InputError(c.where + ": the robots on one host share one plant_simulator process, so their `dds` keys "
                         "must agree ('" + c.dds + "' for " + robot + ", '" + it->second + "' for " +
                         list.substr(0, list.rfind(',')) + ")");
    } else if (c.kind != scenario::ComponentKind::sensor) {
      const std::string name = c.process.empty() ? c.component->name() : c.process;
      const std::string program = distributed::executable_for(c.type);
      auto group = std::find_if(procs.begin(), procs.end(), [&](const Process& p) { return p.name == name; });
      if (group != procs.end()) {  // another service of the same `process`
        group->select.back() += "," + c.component->name();
        if (group->program != program) group->program = "component_host";
        continue;
      }
      Process p;
      p.name = name;
      p.program = program;
      p.select = {"--components", c.component->name()};
      p.restart = c.restart;
      p.vendor = c.dds;
      procs.push_back(p);
    }
  }
  std::set<std::string> robot_hosts;  // over the whole scenario, so names agree on every host
  for (const auto& c : sc.components)
    if (c.kind == scenario::ComponentKind::plant) robot_hosts.insert(c.host);
  std::vector<Process> sims;
  for (const auto& [h, robots] : robots_by_host) {
    const std::string name = robot_hosts.size() == 1 ? "plant_simulator" : "plant_simulator " + robots;
    Process p;  // plants hold the physical state: never restarted
    p.name = name;
    p.program = "plant_simulator";
    p.select = {"--robots", robots};
    p.vendor = dds_by_host[h];
    sims.push_back(p);
  }
  procs.insert(procs.begin(), sims.begin(), sims.end());
  return procs;
}

/// launch.json's record of what this launcher started: process -> executable and vendor.
nlohmann::ordered_json process_table(const std::vector<Process>& procs) {
  nlohmann::ordered_json t = nlohmann::ordered_json::object();
  for (const auto& p : procs) t[p.name] = {{"program", p.program}, {"vendor", p.vendor}};
  return t;
}

int run_launch(const LaunchOptions& o) {
  std::vector<scenario::Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(scenario::parse_override(s));
  scenario::Scenario sc = scenario::load_scenario(o.scenario, overrides);
  const std::string vendor = !o.dds.empty() ? o.dds : (!sc.dds_vendor.empty() ? sc.dds_vendor : "fast");
  rt::parse_vendor(vendor, "--dds");
  const int domain = o.domain >= 0 ? o.domain : sc.dds_domain;
  const std::string qos_file = o.qos_file.empty() ? rt::default_qos_file() : o.qos_file;
  const auto profiles = rt::QosProfiles::load(qos_file);
  const auto& qos = profiles.get("lockstep");

  if (!o.host.empty() && std::find(sc.hosts.begin(), sc.hosts.end(), o.host) == sc.hosts.end())
    throw InputError("--host " + o.host + ": no such host in " + o.scenario);
  std::vector<Process> procs = plan(sc, o.host);
  // Network: loopback, or this host's address with every host of the scenario as a peer.
  rt::NetworkOptions net;
  if (!o.host.empty() && !sc.host_address.at(o.host).empty()) {
    net.interface_address = sc.host_address.at(o.host);
    net.peers.clear();
    for (const auto& h : sc.hosts) {
      if (sc.host_address.at(h).empty())
        throw InputError(o.scenario + ": hosts." + h + ".address: needed when hosts have addresses");
      net.peers.push_back(sc.host_address.at(h));
    }
  }
  std::string peers;
  for (const auto& p : net.peers) peers += (peers.empty() ? "" : ",") + p;
  // The clock (and the run folder) lives on the first host.
  const bool runs_clock = o.host.empty() || o.host == sc.hosts.front();
  const std::vector<Process> everywhere = plan(sc, "");  // what the clock waits for, on every host
  std::map<std::string, std::string> vendor_of;
  for (const auto& v : o.vendors) {
    const auto eq = v.find('=');
    if (eq == std::string::npos) throw InputError("--vendor " + v + ": expected PROCESS=fast|cyclone");
    rt::parse_vendor(v.substr(eq + 1), "--vendor " + v);
    vendor_of[v.substr(0, eq)] = v.substr(eq + 1);
  }
  // --external: a process the scenario declares but something else provides (plexus replay,
  // a hardware bridge) on the same topics. Not started; the lockstep clock still waits for it.
  for (const auto& e : o.externals) {
    const auto all = plan(sc, "");
    if (std::none_of(all.begin(), all.end(), [&](const Process& p) { return p.name == e; }))
      throw InputError("--external " + e + ": no such process (processes: plant_simulator or a service name)");
    procs.erase(std::remove_if(procs.begin(), procs.end(), [&](const Process& p) { return p.name == e; }), procs.end());
  }
  auto is_external = [&](const Process& p) {
    return std::find(o.externals.begin(), o.externals.end(), p.name) != o.externals.end();
  };
  // A process's vendor: --vendor, else its scenario `dds` key, else --dds / dds.vendor.
  for (auto& p : procs) p.vendor = vendor_of.count(p.name) ? vendor_of[p.name] : p.vendor.empty() ? vendor : p.vendor;
  std::set<std::string> used{vendor};  // for the headline
  for (const auto& p : procs) used.insert(p.vendor);
  const std::string vendors_label = used.size() == 1 ? vendor : "mixed: fast + cyclone";
  for (const auto& p : plan(sc, "")) vendor_of.erase(p.name);  // names of processes on any host are fine
  if (!vendor_of.empty())
    throw InputError("--vendor " + vendor_of.begin()->first + ": no such process (processes: plant_simulator or a service name)");

  // Every QoS profile the scenario names must exist before anything starts.
  for (const auto& c : sc.components)
    if (!c.qos.empty() && !profiles.contains(c.qos))
      throw InputError(c.where + ".qos: unknown QoS profile '" + c.qos + "' in " + qos_file);

  std::unique_ptr<SignalRecorder> recorder;
  if (!o.record.empty()) {
    if (sc.clock == scenario::ClockMode::realtime)
      throw InputError("--record: records what the lockstep clock receives; in realtime mode run `plexus record`");
    if (!runs_clock) throw InputError("--record: only the host running the clock (" + sc.hosts.front() + ") records");
    recorder = std::make_unique<SignalRecorder>(o.record, qos);  // file errors: exit 2 before anything starts
  }

  init_logging("launch", "", o.quiet ? "error" : "warn");
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::vector<std::string> common{o.scenario, "--domain", std::to_string(domain), "--qos-file", qos_file,
                                  "--timeout", std::to_string(o.timeout), "--interface", net.interface_address,
                                  "--peers", peers};
  for (const auto& s : o.sets) common.insert(common.end(), {"--set", s});

  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(vendor);
  po.domain_id = domain;
  po.name = "plexus launch" + (o.host.empty() ? std::string() : " " + o.host);
  po.network = net;
  auto participant = rt::Participant::create(po);

  const bool realtime = sc.clock == scenario::ClockMode::realtime;
  // Fault injection: --kill PROCESS@SECONDS sends SIGKILL to a process that long after the start.
  std::map<std::string, double> kill_at;
  for (const auto& k : o.kills) {
    const auto at = k.rfind('@');
    double when = -1;
    try {
      when = at == std::string::npos ? -1 : std::stod(k.substr(at + 1));
    } catch (const std::exception&) {
    }
    if (when < 0) throw InputError("--kill " + k + ": expected PROCESS@SECONDS");
    const std::string name = k.substr(0, at);
    if (std::none_of(procs.begin(), procs.end(), [&](const Process& p) { return p.name == name; }))
      throw InputError("--kill " + k + ": no process '" + name + "' on this host");
    if (!realtime) throw InputError("--kill " + k + ": fault injection needs clock.mode realtime");
    kill_at[name] = when;
  }
  // The run folder is fixed now: the children's logs go to <run>/logs/<process>.log (on a
  // host without the clock, to <run>-<host>/logs), each line also on stderr, prefixed.
  const std::string run_dir = !o.out.empty() ? o.out
                              : scenario::default_run_folder(sc.name).string() + (runs_clock ? "" : "-" + o.host);
  StatusConsole console(!o.quiet);
  const ConsoleLogging console_logging(console);
  LogRelay relay(std::filesystem::path(run_dir) / "logs", console);
  auto start_process = [&relay](Process& p) {
    const int fd = relay.open(p.service());
    p.pid = spawn(p.program, p.args, fd);
    ::close(fd);
    std::string cmd = p.program;
    for (const auto& a : p.args) cmd += " " + a;
    relay.note(p.service(), "started pid " + std::to_string(p.pid) + ": " + cmd);
  };
  FaultClock fault;
  std::atomic<bool> run_active{true};
  for (auto& p : procs) {
    std::vector<std::string> args = common;
    args.insert(args.end(), p.select.begin(), p.select.end());
    args.insert(args.end(), {"--dds", p.vendor, "--mode", realtime ? "realtime" : "lockstep"});
    p.args = args;
    start_process(p);
  }
  // A child that dies ends the run at once, with its name and exit code.
  std::string died;
  std::atomic<bool> watching{true};
  std::thread watcher([&] {
    while (watching) {
      const int64_t started = fault.run_start_ns.load();
      for (auto& p : procs) {
        auto k = kill_at.find(p.name);
        if (started && k != kill_at.end() && p.pid > 0 && monotonic_ns() - started >= static_cast<int64_t>(k->second * 1e9)) {
          ::kill(p.pid, SIGKILL);
          fault.killed_ns = monotonic_ns();
          spdlog::warn("fault injection: killed {} at {:.2f} s", p.service(), k->second);
          kill_at.erase(k);
        }
        int status = 0;
        if (p.pid > 0 && exited(p.pid, status)) {
          relay.note(p.service(), "pid " + std::to_string(p.pid) + " exited with code " + std::to_string(status));
          p.pid = 0;
          const bool restart = realtime && run_active &&
                               (p.restart == "always" || (status != 0 && p.restart == "on_failure"));
          if (restart) {
            start_process(p);
            ++p.restarts;
            spdlog::warn("{} exited with code {}: restarted ({} restarts)", p.service(), status, p.restarts);
          } else if (status != 0 && died.empty()) {
            died = p.service() + " exited with code " + std::to_string(status);
            g_stop = true;
          }
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  auto stop_all = [&] {
    watching = false;
    if (watcher.joinable()) watcher.join();
    for (auto& p : procs)
      if (p.pid > 0) stop(p.pid), p.pid = 0;
    relay.drain();  // the children's last lines before the launcher's verdict
  };
  // Whatever ends the run (an error from DDS included), the watcher is joined and no child
  // outlives the launcher.
  struct StopOnExit {
    const decltype(stop_all)& stop;
    ~StopOnExit() { stop(); }
  } stop_on_exit{stop_all};
  auto failure = [&](const std::string& what) {
    stop_all();
    std::fprintf(stderr, "plexus launch: %s\n", died.empty() ? what.c_str() : died.c_str());
    return 1;
  };

  scenario::RunLog log;
  double wall = 0;
  struct Response {  // lockstep: a producer's step response, over the run
    uint64_t samples = 0;
    int windows = 0;
    double p50_sum = 0, worst_p99 = 0;
  };
  std::map<std::string, Response> responses;
  if (!runs_clock) {
    // Another host runs the clock: serve until our processes end with the run.
    auto running = [&] {
      for (const auto& p : procs)
        if (p.pid > 0) return true;
      return false;
    };
    while (running() && !g_stop) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stop_all();
    if (!died.empty()) return failure(died);
    if (!o.quiet) std::fprintf(stderr, "plexus launch --host %s: %zu processes done\n", o.host.c_str(), procs.size());
    return 0;
  }
  if (realtime) {
    RealtimeResult r;
    try {
      std::vector<Process> all = everywhere;  // monitored through heartbeats: not the external ones
      all.erase(std::remove_if(all.begin(), all.end(), is_external), all.end());
      r = run_realtime(sc, *participant, profiles, all, 30.0, fault, console);
      run_active = false;
      console.clear();
    } catch (const distributed::LockstepError& e) {
      return failure(e.what());
    }
    stop_all();
    if (!died.empty()) return failure(died);
    RunSummary summary;
    char headline[256];
    std::snprintf(headline, sizeof headline, "scenario %s: realtime over %zu processes (%s), %.3g s", sc.name.c_str(),
                  everywhere.size(), vendors_label.c_str(), r.wall);
    summary.headline = headline;
    summary.extra["processes"] = process_table(procs);
    summary.extra["services"] = r.services;
    summary.extra["command_latency"] = r.latency;
    nlohmann::ordered_json restarts = nlohmann::ordered_json::object();
    for (const auto& p : procs)
      if (p.restarts) restarts[p.service()] = p.restarts;
    summary.extra["restarts"] = restarts;
    if (!r.fault.empty()) summary.extra["fault"] = r.fault;
    for (const auto& [name, l] : r.latency.items()) {
      char line[256];
      std::snprintf(line, sizeof line, "latency sensor -> %s: p50 %.0f us, p99 %.0f us (%d samples)", name.c_str(),
                    l["p50_us"].get<double>(), l["p99_us"].get<double>(), l["samples"].get<int>());
      summary.lines.push_back(line);
    }
    const int rc = finish_run(sc, r.log, r.wall, run_dir, o.json, o.quiet, summary);
    if (o.report) print_report(run_dir, o.json);
    return rc;
  }
  try {
    distributed::LockstepClock clock(sc, *participant, qos, {.timeout_s = o.timeout});
    clock.wait_ready(static_cast<int>(everywhere.size()), 30.0, g_stop);
    const int64_t start = monotonic_ns();
    // The live status line, once a second: progress, step rate, the slowest producer.
    std::vector<distributed::LockstepClock::ProducerStatus> status;
    int64_t status_at = start, steps_at = 0;
    auto observe = [&](int64_t k, int64_t n) {
      const int64_t now = monotonic_ns();
      if (now - status_at < 1'000'000'000 && k != n) return;
      clock.producer_status(status);
      const double dt = static_cast<double>(now - status_at) * 1e-9;
      const double rate = dt > 0 ? static_cast<double>(k - steps_at) / dt : 0.0;
      status_at = now;
      steps_at = k;
      for (const auto& p : status) {
        auto& acc = responses[p.producer];
        if (p.samples == 0) continue;
        acc.windows += 1;
        acc.p50_sum += p.response_p50_us;
        acc.worst_p99 = std::max(acc.worst_p99, p.response_p99_us);
        acc.samples += p.samples;
      }
      const auto slow = std::max_element(status.begin(), status.end(), [](const auto& a, const auto& b) {
        return a.response_p99_us < b.response_p99_us;
      });
      char line[512];
      std::snprintf(line, sizeof line, "t %.1f/%.0f s (%3.0f%%) | %.0f steps/s, %.2fx realtime | slowest: %s p99 %.0f us",
                    static_cast<double>(k) * sc.step, sc.duration, 100.0 * static_cast<double>(k) / static_cast<double>(n),
                    rate, rate * sc.step, slow == status.end() ? "-" : slow->producer.c_str(),
                    slow == status.end() ? 0.0 : slow->response_p99_us);
      console.status(line);
    };
    log = clock.run(g_stop, observe, recorder ? recorder->tap(clock.signals()) : distributed::LockstepClock::SampleTap{});
    wall = static_cast<double>(monotonic_ns() - start) * 1e-9;
    console.clear();
  } catch (const distributed::LockstepError& e) {
    return failure(e.what());
  }
  stop_all();
  if (recorder) recorder->write();

  const double steps_per_s = wall > 0 ? static_cast<double>(sc.steps + 1) / wall : 0.0;
  RunSummary summary;
  char headline[256];
  std::snprintf(headline, sizeof headline, "scenario %s: %lld steps in lockstep over %zu processes (%s), %.3g s, %.0f steps/s",
                sc.name.c_str(), static_cast<long long>(sc.steps), everywhere.size(), vendors_label.c_str(), wall, steps_per_s);
  summary.headline = headline;
  summary.extra["steps_per_s"] = steps_per_s;
  summary.extra["processes"] = process_table(procs);
  nlohmann::ordered_json resp = nlohmann::ordered_json::object();
  for (const auto& [producer, acc] : responses)
    resp[producer] = {{"samples", acc.samples},
                      {"response_p50_us", acc.windows ? acc.p50_sum / acc.windows : 0.0},
                      {"response_p99_us_worst_second", acc.worst_p99}};
  summary.extra["response"] = resp;
  const int rc = finish_run(sc, log, wall, run_dir, o.json, o.quiet, summary);
  if (o.report) print_report(run_dir, o.json);
  return rc;
}

}  // namespace

Command add_launch_command(CLI::App& root) {
  auto o = std::make_shared<LaunchOptions>();
  Command c;
  c.app = root.add_subcommand("launch", "Run a scenario distributed over DDS (lockstep), one process per service");
  c.app->add_option("scenario", o->scenario, "Scenario file (YAML)")->required();
  c.app->add_option("--host", o->host, "Start only the processes assigned to this host of the scenario");
  c.app->add_option("--dds", o->dds, "DDS vendor of the clock and of every process without a `dds` key in the scenario (default: dds.vendor, else fast)");
  c.app->add_option("--kill", o->kills, "Fault injection (realtime): SIGKILL PROCESS at SECONDS, as PROCESS@SECONDS");
  c.app->add_option("--external", o->externals,
                     "Do not start PROCESS: plexus replay or a hardware bridge provides its topics (repeatable)");
  c.app->add_option("--record", o->record,
                    "Lockstep: write every signal sample the clock receives to this recording (plexus replay)");
  c.app->add_option("--vendor", o->vendors, "Vendor of one process: PROCESS=fast|cyclone (repeatable)");
  c.app->add_option("--domain", o->domain, "DDS domain id (default: the scenario's)")->check(CLI::Range(0, 232));
  c.app->add_option("--set", o->sets, "Override a scenario value: dotted.key=value (repeatable)");
  c.app->add_option("--out", o->out, "Run folder (default runs/<scenario>-<UTC time>)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles (default deploy/qos.yaml)");
  c.app->add_option("--timeout", o->timeout, "Seconds a process may stay silent before the run fails");
  c.app->add_flag("--json", o->json, "Print the metrics (and steps_per_s) as one JSON object");
  c.app->add_flag("--quiet,-q", o->quiet, "No live status line");
  c.app->add_flag("--report", o->report, "Then plot the run and print its metrics against the expectations (plexus report)");
  c.run = [o] { return run_launch(*o); };
  return c;
}

}  // namespace plexus::cli
