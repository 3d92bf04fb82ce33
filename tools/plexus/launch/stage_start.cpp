// Stage 3 of plexus launch: the launcher's own participant and run folder, then every
// process of this host started with its part of the scenario, and watched (stages.hpp).
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "plexus/runtime/vendor.hpp"
#include "plexus/scenario/step_executor.hpp"
#include "preflight.hpp"
#include "run_result.hpp"
#include "stages.hpp"

namespace plexus::cli {
namespace {

/// --record: the lockstep clock's samples, to a file created now (file errors: exit 2).
std::unique_ptr<SignalRecorder> open_recorder(const LaunchOptions& o, const LaunchPlan& plan) {
  if (o.record.empty()) return nullptr;
  if (plan.realtime)
    throw InputError("--record: records what the lockstep clock receives; in realtime mode run `plexus record`");
  if (!plan.runs_clock)
    throw InputError("--record: only the host running the clock (" + plan.sc.hosts.front() + ") records");
  return std::make_unique<SignalRecorder>(o.record, plan.lockstep_qos);
}

std::unique_ptr<rt::Participant> launcher_participant(const LaunchOptions& o, const LaunchPlan& plan) {
  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(plan.vendor);
  po.domain_id = plan.domain;
  po.name = "plexus launch" + (o.host.empty() ? std::string() : " " + o.host);
  po.network = plan.net;
  po.security = plan.security.launcher;
  po.naming = rt::parse_naming(plan.sc.dds_naming, "dds.naming");
  return rt::Participant::create(po);
}

/// The run folder (on a host without the clock, <run>-<host>), the status line, the log
/// relay (each child's lines to <run>/logs/<process>.log and, prefixed, to stderr), and the
/// other hosts' shares and the launcher's keepalives, which may stop the run from now on.
void open_run_folder(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run) {
  run.run_dir = scenario::prepare_run_folder(o.out, plan.sc.name, plan.runs_clock ? "" : "-" + o.host).string();
  // Once per run: the services' own processes keep quiet.
  if (plan.runs_clock) log_scenario_warnings(plan.sc, run.run_dir);
  run.console.emplace(!o.quiet);
  run.console_logging.emplace(*run.console);
  run.relay.emplace(std::filesystem::path(run.run_dir) / "logs", *run.console);
  const int processes = static_cast<int>(plan.procs.size());
  if (run.remotes) {
    run.remotes->start(*run.relay, processes, g_launch_stop);
    run.console->set_hosts([&run] { return run.remotes->health(); });
  }
  if (plan.session) plan.session->watch(g_launch_stop, processes, [] { return running_children(); });
}

/// Writes `p`'s part of the scenario (launch_plan.hpp part_document) into `dir`; returns the file.
std::string write_part(const std::filesystem::path& dir, const scenario::Scenario& sc, const Process& p) {
  std::string file_name = p.name;
  std::replace(file_name.begin(), file_name.end(), ' ', '_');
  const std::string part_file = (dir / (file_name + ".yaml")).string();
  YAML::Emitter yaml;
  yaml << part_document(sc, p);
  std::FILE* f = std::fopen(part_file.c_str(), "w");
  const bool written = f && std::fputs(yaml.c_str(), f) >= 0;
  if (!(f && std::fclose(f) == 0 && written))
    throw InputError(part_file + ": cannot write this process's part of the scenario");
  return part_file;
}

/// The DDS options every child takes alike (ServiceDdsOptions; plexus replay's the same).
std::vector<std::string> dds_args(const LaunchPlan& plan, const std::string& vendor) {
  const scenario::Scenario& sc = plan.sc;
  return {"--dds",      vendor,        "--domain",           std::to_string(plan.domain),
          "--qos-file", plan.qos_file, "--interface",        plan.net.interface_address,
          "--peers",    plan.peers,    "--transport",        sc.dds_transport,
          "--naming",   sc.dds_naming, "--max-participants", std::to_string(plan.net.max_participants_per_host)};
}

/// The command line of `p`: a service with its part, or `plexus replay` of a robot's topics.
std::vector<std::string> process_args(const LaunchOptions& o, const LaunchPlan& plan, const Process& p,
                                      const std::string& part_file) {
  const scenario::Scenario& sc = plan.sc;
  std::vector<std::string> args{"--part", part_file, "--service", p.service(), "--timeout", std::to_string(o.timeout)};
  const std::vector<std::string> dds = dds_args(plan, p.vendor);
  args.insert(args.end(), dds.begin(), dds.end());
  args.insert(args.end(), {"--mode", plan.realtime ? "realtime" : "lockstep"});
  if (plan.realtime) args.push_back("--start-signal");
  if (plan.realtime && p.priority > 0) args.insert(args.end(), {"--priority", std::to_string(p.priority)});
  if (plan.realtime && p.cpu >= 0) args.insert(args.end(), {"--cpu", std::to_string(p.cpu)});
  if (p.program == "replay") {  // plexus replay of the robot's topics, not a service
    args = replay_args(sc, p);
    args.insert(args.end(), dds.begin(), dds.end());
  }
  const auto security_args = plan.security.args(p.name);
  args.insert(args.end(), security_args.begin(), security_args.end());
  return args;
}

/// --foxglove PORT: foxglove_bridge on the run's domain, with the launcher's DDS options; its
/// output to <run>/logs/foxglove_bridge.log. A port in use ends the launch before the run.
void start_foxglove_bridge(const LaunchOptions& o, const LaunchPlan& plan, LaunchRun& run) {
  if (plan.sc.security.enabled)
    throw InputError("--foxglove: not with DDS Security yet (the bridge has no identity of its own)");
  const std::string log = (std::filesystem::path(run.run_dir) / "logs" / "foxglove_bridge.log").string();
  const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(log + ": cannot create the bridge's log");
  std::vector<std::string> args = dds_args(plan, plan.vendor);
  args.insert(args.end(), {"--port", std::to_string(o.foxglove)});
  try {
    run.foxglove_bridge = spawn("foxglove_bridge", args, fd);
  } catch (const std::exception& e) {
    ::close(fd);
    throw InputError(std::string("--foxglove: cannot start foxglove_bridge: ") + e.what());
  }
  ::close(fd);
  // It listens within a moment, or stops at once with one line (a port in use).
  for (int i = 0; i < 20; ++i) {
    int status = 0;
    if (exited(run.foxglove_bridge, status)) {
      run.foxglove_bridge = 0;
      throw InputError("--foxglove: foxglove_bridge stopped at once (" + log + " says why)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  std::fprintf(stderr, "plexus launch: Foxglove live view on ws://127.0.0.1:%d (docs/viewing.md)\n", o.foxglove);
}

/// --monitor PORT: the run's page (web_monitor.hpp), listening before any process starts, so
/// that a port in use ends the launch with nothing started.
std::unique_ptr<WebMonitor> open_monitor(const LaunchOptions& o, LaunchPlan& plan) {
  if (o.monitor <= 0 || !plan.runs_clock) return nullptr;
  if (!plan.realtime)
    throw InputError(
        "--monitor: realtime runs only (clock.mode: realtime); a lockstep run shows its progress on "
        "the status line");
  nlohmann::json signals = nlohmann::json::array();
  const scenario::StepExecutor wiring(plan.sc, std::vector<bool>(plan.sc.components.size(), false));
  for (const auto& s : wiring.signals()) signals.push_back({{"name", s.name}, {"fields", s.fields}});
  auto monitor = std::make_unique<WebMonitor>(o.monitor, nlohmann::json{{"scenario", plan.sc.name},
                                                                        {"mode", "realtime"},
                                                                        {"vendor", plan.vendors_label},
                                                                        {"signals", std::move(signals)}});
  std::fprintf(stderr, "plexus launch: monitor on http://127.0.0.1:%d/ (docs/viewing.md)\n", o.monitor);
  return monitor;
}

}  // namespace

void start_launch(const LaunchOptions& o, LaunchPlan& plan, LaunchRun& run) {
  run.recorder = open_recorder(o, plan);
  run.monitor = open_monitor(o, plan);
  init_logging("plexus launch", "", "warn");  // --quiet drops the status line, not the warnings
  stop_on_signal(SIGINT);
  stop_on_signal(SIGTERM);
  run.participant = launcher_participant(o, plan);
  auto kill_at = parse_kills(o.kills, plan.procs, plan.realtime);
  open_run_folder(o, plan, run);
  run.supervisor.emplace(plan.procs, *run.relay, run.fault, run.run_active, g_launch_stop, plan.realtime,
                         std::move(kill_at));
  // Each process gets its own part of the scenario and builds only that (launch_plan.hpp).
  const std::filesystem::path parts_dir = std::filesystem::path(run.run_dir) / "parts";
  std::error_code ec;
  std::filesystem::create_directories(parts_dir, ec);
  if (ec) throw InputError(parts_dir.string() + ": cannot create the folder: " + ec.message());
  for (auto& p : plan.procs) {
    p.args = process_args(o, plan, p, write_part(parts_dir, plan.sc, p));
    run.supervisor->start(p);
  }
  if (o.foxglove > 0 && plan.runs_clock) start_foxglove_bridge(o, plan, run);
  // A child that dies ends the run, with its name and exit code (realtime: after a grace
  // during which the others' reaction is recorded).
  run.supervisor->watch();
  run.supervising = true;
  run.launched_ns = monotonic_ns();
}

}  // namespace plexus::cli
