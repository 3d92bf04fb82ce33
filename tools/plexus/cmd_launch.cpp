// plexus launch SCENARIO [--dds fast|cyclone] [--vendor PROCESS=VENDOR ...] [--set k=v ...] [--json]
//
// Runs a scenario distributed over DDS in lockstep: the robots' plants and sensors in a
// plant_simulator process, each service in its own component_host process, and the
// lockstep clock in this process. Writes the same run folder and metrics as `plexus sim`
// (so the digests can be compared) and reports steps_per_s. Children never outlive it.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "child_process.hpp"
#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/lockstep.hpp"
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
  std::string dds, out, qos_file;
  int domain = -1;
  double timeout = 10.0;
  bool json = false, quiet = false;
};

/// One child process: a name, the executable and its selection argument.
struct Process {
  std::string name;
  std::string program;
  std::vector<std::string> select;
  std::string vendor;
  pid_t pid = 0;
};

std::vector<Process> plan(const scenario::Scenario& sc) {
  std::vector<Process> procs;
  bool any_physical = false;
  for (const auto& c : sc.components) {
    if (c.kind == scenario::ComponentKind::plant || c.kind == scenario::ComponentKind::sensor)
      any_physical = true;
    else
      procs.push_back({c.component->name(), "component_host", {"--components", c.component->name()}, "", 0});
  }
  if (any_physical) procs.insert(procs.begin(), Process{"plant_simulator", "plant_simulator", {}, "", 0});
  return procs;
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

  std::vector<Process> procs = plan(sc);
  std::map<std::string, std::string> vendor_of;
  for (const auto& v : o.vendors) {
    const auto eq = v.find('=');
    if (eq == std::string::npos) throw InputError("--vendor " + v + ": expected PROCESS=fast|cyclone");
    rt::parse_vendor(v.substr(eq + 1), "--vendor " + v);
    vendor_of[v.substr(0, eq)] = v.substr(eq + 1);
  }
  for (auto& p : procs) {
    p.vendor = vendor_of.count(p.name) ? vendor_of[p.name] : vendor;
    vendor_of.erase(p.name);
  }
  if (!vendor_of.empty())
    throw InputError("--vendor " + vendor_of.begin()->first + ": no such process (processes: plant_simulator or a service name)");

  init_logging("launch", "", o.quiet ? "error" : "warn");
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::vector<std::string> common{o.scenario, "--domain", std::to_string(domain), "--qos-file", qos_file,
                                  "--timeout", std::to_string(o.timeout)};
  for (const auto& s : o.sets) common.insert(common.end(), {"--set", s});

  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(vendor);
  po.domain_id = domain;
  po.name = "plexus launch";
  auto participant = rt::Participant::create(po);
  distributed::LockstepClock clock(sc, *participant, qos, {.timeout_s = o.timeout});

  for (auto& p : procs) {
    std::vector<std::string> args = common;
    args.insert(args.end(), p.select.begin(), p.select.end());
    args.insert(args.end(), {"--dds", p.vendor});
    p.pid = spawn(p.program, args);
  }
  auto stop_all = [&procs] {
    for (auto& p : procs)
      if (p.pid > 0) stop(p.pid), p.pid = 0;
  };

  scenario::RunLog log;
  double wall = 0;
  try {
    clock.wait_ready(static_cast<int>(procs.size()), 30.0, g_stop);
    scenario::ProgressBar bar(!o.quiet);
    const int64_t start = monotonic_ns();
    log = clock.run(g_stop, [&](int64_t k, int64_t n) { bar.update(k, n); });
    wall = static_cast<double>(monotonic_ns() - start) * 1e-9;
    bar.finish();
  } catch (const distributed::LockstepError& e) {
    stop_all();
    std::fprintf(stderr, "plexus launch: %s\n", e.what());
    return 1;
  }
  stop_all();

  const scenario::Evaluation ev = scenario::evaluate(sc, log);
  const auto dir = o.out.empty() ? scenario::default_run_folder(sc.name) : std::filesystem::path(o.out);
  scenario::write_run_folder(dir, sc, log, ev, wall);
  const double steps_per_s = wall > 0 ? static_cast<double>(sc.steps + 1) / wall : 0.0;
  if (o.json) {
    auto j = ev.to_json();
    j["steps_per_s"] = steps_per_s;
    std::cout << j.dump() << std::endl;
  } else {
    std::printf("scenario %s: %lld steps in lockstep over %zu processes (%s), %.3g s, %.0f steps/s\n", sc.name.c_str(),
                static_cast<long long>(sc.steps), procs.size(), vendor.c_str(), wall, steps_per_s);
    for (const auto& [name, r] : ev.metrics)
      std::printf("  %-24s %s\n", name.c_str(), scenario::format_number(r.value).c_str());
    std::printf("  %-24s %s\n", "digest", ev.digest.c_str());
  }
  if (!o.quiet) std::fprintf(stderr, "run folder: %s\n", dir.string().c_str());
  for (const auto& f : ev.failures) std::fprintf(stderr, "%s\n", f.c_str());
  return ev.failures.empty() ? 0 : 1;
}

}  // namespace

Command add_launch_command(CLI::App& root) {
  auto o = std::make_shared<LaunchOptions>();
  Command c;
  c.app = root.add_subcommand("launch", "Run a scenario distributed over DDS (lockstep), one process per service");
  c.app->add_option("scenario", o->scenario, "Scenario file (YAML)")->required();
  c.app->add_option("--dds", o->dds, "DDS vendor of every process (default: the scenario's, else fast)");
  c.app->add_option("--vendor", o->vendors, "Vendor of one process: PROCESS=fast|cyclone (repeatable)");
  c.app->add_option("--domain", o->domain, "DDS domain id (default: the scenario's)")->check(CLI::Range(0, 232));
  c.app->add_option("--set", o->sets, "Override a scenario value: dotted.key=value (repeatable)");
  c.app->add_option("--out", o->out, "Run folder (default runs/<scenario>-<UTC time>)");
  c.app->add_option("--qos-file", o->qos_file, "QoS profiles (default deploy/qos.yaml)");
  c.app->add_option("--timeout", o->timeout, "Seconds a process may stay silent before the run fails");
  c.app->add_flag("--json", o->json, "Print the metrics (and steps_per_s) as one JSON object");
  c.app->add_flag("--quiet,-q", o->quiet, "No progress bar");
  c.run = [o] { return run_launch(*o); };
  return c;
}

}  // namespace plexus::cli
