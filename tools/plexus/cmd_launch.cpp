// plexus launch SCENARIO [--host H] [--dds fast|cyclone] [--vendor PROCESS=VENDOR ...] [--set k=v ...] [--json]
//
// Runs a scenario distributed over DDS: the robots' plants and sensors in a plant_simulator
// process, each service (or `process` group) in its own process (launch_plan.hpp), children's
// logs relayed and collected (log_relay.hpp). Lockstep: the clock runs here and the run gives
// the digest of `plexus sim`, with steps_per_s. Realtime: restarts, fault injection and the
// latency record (realtime_run.hpp). Writes the same run folder and metrics as `plexus sim`.
// Children never outlive it.
#include <signal.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <algorithm>
#include <map>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "preflight.hpp"
#include "remote_session.hpp"
#include "remote_share.hpp"
#include "launch_plan.hpp"
#include "launch_security.hpp"
#include "realtime_run.hpp"
#include "log_relay.hpp"
#include "qos_names.hpp"
#include "status_console.hpp"
#include "command.hpp"
#include "run_result.hpp"
#include "signal_recorder.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/progress_bar.hpp"
#include "plexus/evaluation/run_folder.hpp"

namespace plexus::cli {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};  // the SIGINT / SIGTERM that interrupted the run (0: none)
void on_signal(int s) {
  g_signal = s;
  g_stop = true;
}

/// Realtime: how long a run goes on after a process died for good (a plant simulator, a
/// service with `restart: never`), recording the others' reaction, before it fails. A
/// second: many input deadlines at any rate a scenario uses (3 periods: 30 ms at 100 Hz).
constexpr int64_t kFatalGraceNs = 1'000'000'000;

struct LaunchOptions {
  std::string scenario;
  std::vector<std::string> sets;
  std::vector<std::string> vendors;  // PROCESS=VENDOR
  std::vector<std::string> kills;    // PROCESS@SECONDS (fault injection, realtime)
  std::vector<std::string> externals;  // processes provided from outside (replay, hardware bridge)
  std::string dds, out, qos_file, host, record;
  std::string transport;  // --transport: dds.transport of the scenario, overridden (travels as a --set)
  int domain = -1;
  double timeout = 10.0;
  bool json = false, quiet = false, report = false;
  // Hosts over ssh (remote_share.hpp): --ssh-config, --allow-clock-offset; --remote is the
  // share a launcher started over ssh; --inject-clock-offset HOST=SECONDS fakes an offset (tests).
  std::string ssh_config;
  bool allow_clock_offset = false, remote = false;
  std::vector<std::string> clock_injections;
};

int run_launch(LaunchOptions o) {
  const int64_t command_ns = monotonic_ns();
  std::unique_ptr<RemoteSession> session;
  RemoteRequest request;
  if (!o.remote && o.scenario.empty()) throw InputError("scenario: required (the scenario file)");
  if (o.remote) {  // started over ssh: the scenario and the options come from the launcher
    std::signal(SIGHUP, on_signal);
    session = std::make_unique<RemoteSession>(PLEXUS_VERSION);
    request = session->read_request();
    o.host = request.host, o.scenario = request.scenario_origin, o.sets = request.sets, o.vendors = request.vendors;
    o.externals = request.externals, o.dds = request.dds, o.qos_file = request.qos_file, o.out = request.out;
    o.domain = request.domain, o.timeout = request.timeout;
  }
  // --transport is dds.transport overridden: as a --set it reaches the hosts over ssh too.
  if (!o.remote && !o.transport.empty()) {
    rt::parse_transport(o.transport, "--transport");
    o.sets.push_back("dds.transport=" + o.transport);
    o.transport.clear();
  }
  std::vector<scenario::Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(scenario::parse_override(s));
  scenario::Scenario sc = session ? scenario::load_scenario_text(request.scenario_text, o.scenario, overrides)
                                  : scenario::load_scenario(o.scenario, overrides);
  // One command, many hosts: a scenario whose hosts name ssh destinations, launched without
  // --host, runs here as its first host and starts the others over ssh.
  const bool one_command = o.host.empty() && !o.remote && uses_ssh(sc);
  const std::vector<std::string> remote_hosts = one_command ? ssh_hosts(sc) : std::vector<std::string>{};
  if (one_command) o.host = sc.hosts.front();
  for (const auto& [robot, src] : sc.sources)
    if (sc.clock != scenario::ClockMode::realtime)
      throw InputError(src.where + ": robot " + robot + "'s source is " + scenario::to_string(src.type) +
                       ", which keeps its own time: set clock.mode: realtime (or --set clock.mode=realtime)");
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
  net.transport = rt::parse_transport(sc.dds_transport, o.scenario + ": dds.transport");
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

  // DDS Security: every participant's identity checked, and a mixed deployment whose
  // handshakes would fail refused, before anything starts (launch_security.hpp).
  std::vector<Process> all_vendors = plan(sc, "");
  for (auto& p : all_vendors) {
    const auto named = std::find_if(o.vendors.begin(), o.vendors.end(), [&](const std::string& v) { return v.rfind(p.name + "=", 0) == 0; });
    p.vendor = named != o.vendors.end() ? named->substr(p.name.size() + 1) : p.vendor.empty() ? vendor : p.vendor;
  }
  all_vendors.erase(std::remove_if(all_vendors.begin(), all_vendors.end(), is_external), all_vendors.end());
  const LaunchSecurity security = [&] {
    try {
      return plan_security(sc, all_vendors, vendor);
    } catch (const InputError& e) {  // a section set by --set has no line: name the override
      throw InputError(scenario::attribute_to_override(e.what(), o.scenario, overrides));
    }
  }();

  // Every QoS profile the scenario names must exist before anything starts.
  check_qos_names(sc, profiles, qos_file);

  // Preflight (remote_share.hpp), before anything starts: every host reachable, the same
  // version, the same scenario digest, its address on an interface, clocks that agree.
  std::unique_ptr<RemoteShares> remotes;
  const std::string digest = scenario_digest(sc, qos_file);
  if (session) {
    RemoteReady ready{digest, qos_file, net.interface_address, address_on_interface(net.interface_address),
                      static_cast<int>(procs.size())};
    if (!session->ready_and_wait_go(ready, request.clock_injection_ns)) return 1;  // the launcher gave up
  } else if (one_command) {
    remotes = preflight_hosts(sc, o.host, net.interface_address, remote_hosts,
                              {o.scenario, o.ssh_config, o.out, o.dds, o.qos_file, o.sets, o.vendors, o.externals,
                               o.clock_injections, domain, o.timeout, o.allow_clock_offset},
                              PLEXUS_VERSION, digest);
  }

  std::unique_ptr<SignalRecorder> recorder;
  if (!o.record.empty()) {
    if (sc.clock == scenario::ClockMode::realtime)
      throw InputError("--record: records what the lockstep clock receives; in realtime mode run `plexus record`");
    if (!runs_clock) throw InputError("--record: only the host running the clock (" + sc.hosts.front() + ") records");
    recorder = std::make_unique<SignalRecorder>(o.record, qos);  // file errors: exit 2 before anything starts
  }

  init_logging("plexus launch", "", "warn");  // --quiet drops the status line, not the warnings
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::vector<std::string> common{"--domain", std::to_string(domain), "--qos-file", qos_file,
                                  "--timeout", std::to_string(o.timeout), "--interface", net.interface_address,
                                  "--peers", peers, "--transport", sc.dds_transport};

  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(vendor);
  po.domain_id = domain;
  po.name = "plexus launch" + (o.host.empty() ? std::string() : " " + o.host);
  po.network = net;
  po.security = security.launcher;
  auto participant = rt::Participant::create(po);
  // Every return from here on arms the teardown bound (plexus/base/teardown_deadline.hpp)
  // before the participant is deleted: a vendor's shutdown that hangs cannot keep the
  // launcher, and what waits for it, from ending.
  const auto done = [](int rc) { return exit_within(rc, kTeardownDeadlineS, "plexus launch"); };

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
  const std::string run_dir = scenario::prepare_run_folder(o.out, sc.name, runs_clock ? "" : "-" + o.host).string();
  if (runs_clock) log_scenario_warnings(sc, run_dir);  // once per run: the services' own processes keep quiet
  StatusConsole console(!o.quiet);
  const ConsoleLogging console_logging(console);
  LogRelay relay(std::filesystem::path(run_dir) / "logs", console);
  if (remotes) {
    remotes->start(relay, static_cast<int>(procs.size()), g_stop);
    console.set_hosts([&remotes] { return remotes->health(); });
  }
  if (session) session->watch(g_stop, static_cast<int>(procs.size()), [] { return running_children(); });
  auto start_process = [&relay](Process& p) {
    const int fd = relay.open(p.service());
    p.pid = spawn(p.executable(), p.args, fd);
    ::close(fd);
    std::string cmd = p.executable();
    for (const auto& a : p.args) cmd += " " + a;
    relay.note(p.service(), "started pid " + std::to_string(p.pid) + ": " + cmd);
  };
  FaultClock fault;
  std::atomic<bool> run_active{true};
  // Each process gets its own part of the scenario and builds only that (launch_plan.hpp).
  const std::filesystem::path parts_dir = std::filesystem::path(run_dir) / "parts";
  std::error_code ec;
  std::filesystem::create_directories(parts_dir, ec);
  if (ec) throw InputError(parts_dir.string() + ": cannot create the folder: " + ec.message());
  for (auto& p : procs) {
    std::string file_name = p.name;
    std::replace(file_name.begin(), file_name.end(), ' ', '_');
    const std::string part_file = (parts_dir / (file_name + ".yaml")).string();
    YAML::Emitter yaml;
    yaml << part_document(sc, p);
    std::FILE* f = std::fopen(part_file.c_str(), "w");
    const bool written = f && std::fputs(yaml.c_str(), f) >= 0;
    if (!(f && std::fclose(f) == 0 && written))
      throw InputError(part_file + ": cannot write this process's part of the scenario");
    std::vector<std::string> args{"--part", part_file, "--service", p.service()};
    args.insert(args.end(), common.begin(), common.end());
    args.insert(args.end(), {"--dds", p.vendor, "--mode", realtime ? "realtime" : "lockstep"});
    if (realtime) args.push_back("--start-signal");
    if (realtime && p.priority > 0) args.insert(args.end(), {"--priority", std::to_string(p.priority)});
    if (realtime && p.cpu >= 0) args.insert(args.end(), {"--cpu", std::to_string(p.cpu)});
    if (p.program == "replay") {  // plexus replay of the robot's topics, not a service
      args = replay_args(sc, p);
      args.insert(args.end(), {"--dds", p.vendor, "--domain", std::to_string(domain), "--qos-file", qos_file,
                               "--interface", net.interface_address, "--peers", peers, "--transport", sc.dds_transport});
    }
    const auto security_args = security.args(p.name);
    args.insert(args.end(), security_args.begin(), security_args.end());
    p.args = args;
    start_process(p);
  }
  // A child that dies ends the run, with its name and exit code (realtime: after a grace
  // during which the others' reaction is recorded).
  std::string died;
  std::string killed_name;    // the process --kill killed (watcher thread only)
  int64_t fatal_stop_ns = 0;  // realtime: when to stop after a death that is not restarted
  std::atomic<bool> watching{true};
  std::thread watcher([&] {
    while (watching) {
      const int64_t started = fault.run_start_ns.load();
      for (auto& p : procs) {
        auto k = kill_at.find(p.name);
        if (started && k != kill_at.end() && p.pid > 0 && monotonic_ns() - started >= static_cast<int64_t>(k->second * 1e9)) {
          ::kill(p.pid, SIGKILL);
          fault.killed_ns = monotonic_ns();
          killed_name = p.name;
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
            // restart_delay (systemd's RestartSec): the restart is due that long after the death.
            p.restart_at_ns = monotonic_ns() + p.restart_delay_ns;
            spdlog::warn("{} exited with code {}: restart in {:.2f} s", p.service(), status, p.restart_delay_ns * 1e-9);
          } else if (status != 0 && died.empty()) {
            died = p.service() + " exited with code " + std::to_string(status);
            // Realtime: the run goes on for kFatalGraceNs, so that the recording shows how the
            // others reacted (their controllers' holds), then fails. Lockstep: at once.
            if (realtime && fault.run_start_ns.load())
              fatal_stop_ns = monotonic_ns() + kFatalGraceNs;
            else
              g_stop = true;
          }
        }
        if (fatal_stop_ns && monotonic_ns() >= fatal_stop_ns) g_stop = true;
        if (p.restart_at_ns && monotonic_ns() >= p.restart_at_ns && run_active) {
          p.restart_at_ns = 0;
          start_process(p);
          if (fault.killed_ns.load() && !fault.respawned_ns.load() && p.name == killed_name) fault.respawned_ns = monotonic_ns();
          ++p.restarts;
          spdlog::warn("{}: restarted ({} restarts)", p.service(), p.restarts);
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  double teardown_s = -1;  // from the end of the run to every process stopped, on every host
  auto stop_all = [&] {
    const int64_t t = monotonic_ns();
    watching = false;
    if (watcher.joinable()) watcher.join();
    for (auto& p : procs)
      if (p.pid > 0) stop(p.pid), p.pid = 0;
    if (remotes) remotes->stop();
    if (teardown_s < 0) teardown_s = static_cast<double>(monotonic_ns() - t) * 1e-9;
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
    const std::string lost = remotes ? remotes->failure() : std::string();  // a lost host is the cause
    const std::string why = !lost.empty() ? lost : died.empty() ? what : died;
    scenario::mark_run_folder(run_dir, "failed: " + why);
    std::fprintf(stderr, "plexus launch: %s\n", why.c_str());
    return done(1);
  };
  const int64_t launched_ns = monotonic_ns();
  auto interrupted = [&] {
    stop_all();
    return done(interrupted_run("plexus launch", g_signal, run_dir, static_cast<double>(monotonic_ns() - launched_ns) * 1e-9));
  };
  auto host_lost = [&] { return remotes && !remotes->failure().empty(); };
  // launch.json and the summary: how long the start and the stop took, and each host's clock.
  double startup_s = -1;
  auto add_hosts = [&](RunSummary& summary) {
    summary.extra["startup_s"] = startup_s;
    summary.extra["teardown_s"] = teardown_s;
    if (!remotes) return;
    summary.extra["hosts"] = remotes->report();
    char line[200];
    std::snprintf(line, sizeof line, "hosts: %zu, every process running %.2f s after the command, all stopped in %.2f s",
                  remote_hosts.size() + 1, startup_s, teardown_s);
    summary.lines.push_back(line);
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
    if (g_signal) return interrupted();
    stop_all();
    if (!died.empty()) return failure(died);
    scenario::mark_run_folder(run_dir, "complete");
    if (session && !session->ended().empty()) {
      std::fprintf(stderr, "plexus launch --host %s: stopped: %s\n", o.host.c_str(), session->ended().c_str());
      return done(0);
    }
    if (!o.quiet) std::fprintf(stderr, "plexus launch --host %s: %zu processes done\n", o.host.c_str(), procs.size());
    return done(0);
  }
  if (realtime) {
    RealtimeResult r;
    try {
      std::vector<Process> all = everywhere;  // monitored through heartbeats: not the external ones
      all.erase(std::remove_if(all.begin(), all.end(), is_external), all.end());
      std::map<std::string, int64_t> host_offsets;  // corrects cross-host latencies (remote_share.hpp)
      for (const auto& h : remote_hosts) host_offsets[h] = remotes->offset(h).offset_ns;
      // Readiness (inputs matched) is awaited for half the services' own wait for the start
      // signal (--timeout), so that they always get it before they give up.
      r = run_realtime(sc, *participant, profiles, all, 30.0, o.timeout / 2, fault, console, g_stop, host_offsets);
      startup_s = static_cast<double>(r.all_running_ns - command_ns) * 1e-9;
      run_active = false;
      console.clear();
    } catch (const distributed::LockstepError& e) {
      if (g_signal) return interrupted();
      return failure(e.what());
    }
    if (g_signal) return interrupted();
    stop_all();
    if (host_lost()) return failure(died);
    RunSummary summary;
    char headline[256];
    std::snprintf(headline, sizeof headline, "scenario %s: realtime over %zu processes (%s), %.3g s", sc.name.c_str(),
                  everywhere.size(), vendors_label.c_str(), r.wall);
    summary.headline = headline;
    summary.extra["processes"] = process_table(procs);
    if (security.enabled) summary.extra["security"] = security.to_json();
    summary.extra["services"] = r.services;
    summary.extra["command_latency"] = r.latency;
    nlohmann::ordered_json restarts = nlohmann::ordered_json::object();
    for (const auto& p : procs)
      if (p.restarts) restarts[p.service()] = p.restarts;
    summary.extra["restarts"] = restarts;
    if (!r.fault.empty()) {
      r.fault["killed"] = killed_name;
      summary.extra["fault"] = r.fault;
    }
    // A process that died for good: the run folder still records what happened, then it fails.
    if (!died.empty()) summary.extra["failure"] = died;
    for (const auto& [name, l] : r.latency.items()) {
      if (l["samples"].get<int>() == 0) continue;  // no sensor sample reached it (an open-loop command)
      char line[320];
      std::snprintf(line, sizeof line, "latency sensor -> %s: p50 %.0f us, p99 %.0f us (%d samples)%s", name.c_str(),
                    l["p50_us"].get<double>(), l["p99_us"].get<double>(), l["samples"].get<int>(),
                    l.contains("clock_offset_corrected_us")
                        ? (", corrected by " + l["clock_offset_corrected_us"].dump() + " us of clock offset").c_str()
                        : "");
      summary.lines.push_back(line);
    }
    add_hosts(summary);
    const int rc = finish_run(sc, r.log, r.wall, run_dir, o.json, o.quiet, summary);
    if (o.report) print_report(run_dir, o.json);
    if (!died.empty()) {
      scenario::mark_run_folder(run_dir, "failed: " + died);  // recorded, but not a complete run
      std::fprintf(stderr, "plexus launch: %s\n", died.c_str());
      return done(1);
    }
    return done(rc);
  }
  std::map<std::string, double> producer_offset_us;  // lockstep responses: per producer on another host
  try {
    distributed::LockstepClock clock(sc, *participant, qos, {.timeout_s = o.timeout});
    clock.wait_ready(static_cast<int>(everywhere.size()), 30.0, g_stop);
    const int64_t start = monotonic_ns();
    startup_s = static_cast<double>(start - command_ns) * 1e-9;
    // A producer on another host stamps its response with that host's clock: correct it.
    for (const auto& c : sc.components)
      if (remotes && !c.host.empty()) producer_offset_us[c.component->name()] = static_cast<double>(remotes->offset(c.host).offset_ns) * 1e-3;
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
        const auto off = producer_offset_us.find(p.producer);
        const double correction = off == producer_offset_us.end() ? 0.0 : off->second;
        acc.windows += 1;
        acc.p50_sum += p.response_p50_us - correction;
        acc.worst_p99 = std::max(acc.worst_p99, p.response_p99_us - correction);
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
    if (g_signal) return interrupted();
    return failure(e.what());
  }
  if (g_signal) return interrupted();
  stop_all();
  if (host_lost()) return failure("");
  if (recorder) recorder->write();

  const double steps_per_s = wall > 0 ? static_cast<double>(sc.steps + 1) / wall : 0.0;
  RunSummary summary;
  char headline[256];
  std::snprintf(headline, sizeof headline, "scenario %s: %lld steps in lockstep over %zu processes (%s), %.3g s, %.0f steps/s",
                sc.name.c_str(), static_cast<long long>(sc.steps), everywhere.size(), vendors_label.c_str(), wall, steps_per_s);
  summary.headline = headline;
  summary.extra["steps_per_s"] = steps_per_s;
  summary.extra["processes"] = process_table(procs);
  if (security.enabled) summary.extra["security"] = security.to_json();
  nlohmann::ordered_json resp = nlohmann::ordered_json::object();
  for (const auto& [producer, acc] : responses) {
    resp[producer] = {{"samples", acc.samples},
                      {"response_p50_us", acc.windows ? acc.p50_sum / acc.windows : 0.0},
                      {"response_p99_us_worst_second", acc.worst_p99}};
    if (producer_offset_us.count(producer))  // on another host: corrected by its clock offset
      resp[producer]["clock_offset_corrected_us"] = producer_offset_us.at(producer);
  }
  summary.extra["response"] = resp;
  add_hosts(summary);
  const int rc = finish_run(sc, log, wall, run_dir, o.json, o.quiet, summary);
  if (o.report) print_report(run_dir, o.json);
  return done(rc);
}

}  // namespace

Command add_launch_command(CLI::App& root) {
  auto o = std::make_shared<LaunchOptions>();
  Command c;
  c.app = root.add_subcommand("launch", "Run a scenario distributed over DDS (lockstep), one process per service");
  c.app->add_option("scenario", o->scenario, "Scenario file (YAML; required but with the internal --remote)");
  c.app->add_option("--host", o->host, "Start only the processes assigned to this host of the scenario");
  c.app->add_option("--dds", o->dds, "DDS vendor of the clock and of every process without a `dds` key in the scenario (default: dds.vendor, else fast)");
  c.app->add_option("--transport", o->transport,
                    "auto, udp or shm: between processes of one host (docs/runtime.md, Transports; default: dds.transport, else auto)");
  c.app->add_option("--kill", o->kills, "Fault injection (realtime): SIGKILL PROCESS at SECONDS, as PROCESS@SECONDS");
  c.app->add_option("--external", o->externals,
                     "Do not start PROCESS: plexus replay or a hardware bridge provides its topics (repeatable)");
  c.app->add_option("--record", o->record,
                    "Lockstep: write every signal sample the clock receives to this recording (plexus replay)");
  c.app->add_option("--vendor", o->vendors, "Vendor of one process: PROCESS=fast|cyclone (repeatable)");
  c.app->add_option("--domain", o->domain, "DDS domain id (default: the scenario's)")->check(CLI::Range(0, 232));
  c.app->add_option("--set", o->sets, "Override a scenario value: dotted.key=value (repeatable)");
  c.app->add_option("-o,--out", o->out, "Run folder (default runs/<scenario>-<UTC time>)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles (default deploy/qos.yaml)");
  c.app->add_option("--timeout", o->timeout, "Seconds a process may stay silent before the run fails")
      ->check(positive_seconds());
  c.app->add_flag("--json", o->json, "Print the metrics (and steps_per_s) as one JSON object");
  c.app->add_flag("--quiet,-q", o->quiet, "No live status line");
  c.app->add_flag("--report", o->report, "Then plot the run and print its metrics against the expectations (plexus report)");
  c.app->add_option("--ssh-config", o->ssh_config,
                    "Hosts reached over ssh (hosts.<h>.ssh): use this ssh configuration file (ssh -F; default ~/.ssh/config)");
  c.app->add_flag("--allow-clock-offset", o->allow_clock_offset,
                  "Realtime over ssh hosts: run even when a host's clock is beyond the offset bound (docs/distributed.md)");
  c.app->add_flag("--remote", o->remote, "Internal: the share of one host, started over ssh by plexus launch")->group("");
  c.app->add_option("--inject-clock-offset", o->clock_injections,
                    "Tests: HOST=SECONDS added to that host's clock readings in the offset exchange")->group("");
  c.run = [o] { return run_launch(*o); };
  return c;
}

}  // namespace plexus::cli
