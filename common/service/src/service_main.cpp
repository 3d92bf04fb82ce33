// The body of every plexus service executable, built-in or a user's (plexus_add_service
// generates each one's main(), which names it): it builds the components this process hosts,
// and only those, from its own parameters, then runs them on DDS in realtime (the default) or
// lockstep. What the service hosts is its declaration (plexus::scenario::find_service).
//
// On its own, from its parameters (a service is a program a stranger can deploy):
//   localisation_observer --robot r1 --params observer.yaml --set L=0.6
//   plant_simulator --robot r1 --params robot.yaml --step 0.001
// It starts at once, publishes its heartbeat on health/<service>, holds its safe output
// while an input is stale, and runs until SIGINT/SIGTERM, then exits 0. Its topics are the
// typed topics of docs/topics.md, so anything that speaks idl/ can feed and read it.
//
// Under `plexus launch`: --part FILE, this process's part of the scenario (its components
// and the schedule of the inputs other processes produce), --start-signal to tick on the
// run's common grid, --mode lockstep to step with the launcher's clock.
//
// Bad parameters: one line naming file, line and key, exit 2.
#include <sys/prctl.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <set>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "plexus/base/cli_style.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/runtime/periodic_loop.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/scenario/plugins.hpp"
#include "plexus/scenario/registry.hpp"
#include "plexus/service/dds_options.hpp"
#include "plexus/service/producer_monitor.hpp"
#include "plexus/service/service_main.hpp"
#include "plexus/service/standalone.hpp"
#include "service_help.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

}  // namespace

namespace {

// Whether a service hosts a component: its own types; a plant-side service also any plant or
// sensor; a host any type. Else the one-line reason, naming where the type runs.
std::string hosting_error(const plexus::scenario::ServiceDeclaration& self,
                          const plexus::scenario::ScenarioComponent& c) {
  using namespace plexus::scenario;
  if (self.role == ServiceRole::host) return "";
  const auto& own = self.component_types;
  if (std::find(own.begin(), own.end(), c.type) != own.end()) return "";
  const bool physical = c.kind == ComponentKind::plant || c.kind == ComponentKind::sensor;
  if (self.role == ServiceRole::plant && physical && !service_declaring(c.type)) return "";
  const std::string home = executable_for(c.type);
  return c.where + ": '" + c.component->name() + "' is a " + c.type + ", which " + self.name + " does not host" +
         (home.empty() ? std::string() : " (it runs in " + home + ")");
}

}  // namespace

int plexus::service::run_service(int argc, char** argv, const std::string& self) {
  using namespace plexus;
  const scenario::ServiceDeclaration* declared = scenario::find_service(self);
  if (!declared) {
    std::fprintf(stderr, "%s: error: no service of that name is declared (plexus_add_service links its declaration)\n",
                 self.c_str());
    return kExitBadInput;
  }
  const scenario::ServiceDeclaration& service = *declared;
  const bool hosts_plant = service.role == scenario::ServiceRole::plant;
  const std::string about = self +
                            ": a plexus service over DDS, on its own (--robot, --params, --set) or as part of `plexus "
                            "launch` (--part)";
  CLI::App app{about};
  // What it runs and its topics, built only when help is asked for.
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h")
      app.footer(scenario::hosted_help(service));
  app.set_version_flag("--version", self + " " + PLEXUS_VERSION);
  std::string part_file, profile = "lockstep", log_level = "warn", mode = "realtime";
  scenario::ServiceDdsOptions net;
  int priority = 0, cpu = -1;
  std::vector<std::string> sets;
  double timeout = 10.0;
  bool start_signal = false;
  scenario::StandaloneSpec alone;
  alone.program = self;
  alone.robot_section = hosts_plant;
  if (hosts_plant)
    alone.command_rate_hz = scenario::kDefaultCommandRateHz;  // --input-rate cmd=1000: a 1 kHz arm controller
  alone.name = self;
  // A host runs whatever --type names; a service defaults to its first type.
  if (service.role != scenario::ServiceRole::host && !service.component_types.empty())
    alone.type = service.component_types.front();
  app.add_option("--part", part_file, "This process's part of a scenario (written by plexus launch)");
  app.add_option("--robot", alone.robot, "Robot whose topics it uses (<robot>/<topic>; default r1)");
  app.add_option("--name", alone.name,
                 "Its name in the scenario it builds alone: its parameters' section and its components' names "
                 "(default: the executable's); --service names the process in heartbeats and logs");
  app.add_option("--params", alone.params_file,
                 hosts_plant ? "YAML robot section: plant and sensors (docs/scenarios.md)"
                             : "YAML parameters of the service (the keys of its scenario section, docs/scenarios.md)");
  if (!hosts_plant) app.add_option("--type", alone.type, "Component type (default: " + alone.type + ")");
  app.add_option("--step", alone.step,
                 "Base step in s (default: 1 / its rate; plant_simulator: the params file's step, else 0.01)")
      ->check(positive("s"));
  app.add_option("--input-rate", alone.input_rates,
                 hosts_plant
                     ? "cmd=HZ: the command's rate (default 100); stale after 3 periods"
                     : "PORT=HZ: the rate an input is produced at, when not its own (staleness: 3 of its periods)");
  app.add_option("--set", sets, "Parameter override key=value (with --part: dotted.key=value of the part)");
  net.add_to(app);
  app.add_option("--profile", profile, "QoS profile of the lockstep topics");
  app.add_option("--timeout", timeout,
                 "Seconds to wait for one input (lockstep) or for the start signal (--start-signal) before failing")
      ->check(positive("s"));
  app.add_option("--mode", mode, "realtime (default) or lockstep (steps with a plexus launch clock)")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  app.add_flag("--start-signal", start_signal, "Realtime: wait for the launcher's start signal (plexus launch)");
  app.add_option("--priority", priority, "Realtime: SCHED_FIFO priority, 1 .. 99 (0: normal scheduling)")
      ->check(fifo_priority());
  app.add_option("--cpu", cpu, "Realtime: pin the loop to this CPU (0, 1, ...)")->check(cpu_index());
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off");
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins,
                 "Load a shared library of component or message types first (docs/sdk.md); repeatable");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e, self);
  }
  if (!part_file.empty()) prctl(PR_SET_PDEATHSIG, SIGTERM);  // under the launcher: never outlive it
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging(self, "", log_level);
    for (const auto& lib : plugins) scenario::load_plugin(lib, "--plugin");
    const bool realtime = mode == "realtime";
    scenario::Scenario sc;
    if (!part_file.empty()) {
      std::vector<scenario::Override> overrides;
      for (const auto& s : sets) overrides.push_back(scenario::parse_override(s));
      sc = scenario::load_scenario(part_file, overrides, {.partial = true});
    } else {
      // Before the component is built: a type this executable does not link is not known here at all.
      const auto& own = service.component_types;
      if (!hosts_plant && service.role != scenario::ServiceRole::host &&
          std::find(own.begin(), own.end(), alone.type) == own.end() && !scenario::service_declaring(alone.type)) {
        std::string list;
        for (const auto& t : own) list += (list.empty() ? "" : ", ") + t;
        throw InputError("--type: " + self + " does not host a " + alone.type + " (it hosts " + list + ")");
      }
      sc = scenario::load_standalone(alone, sets, realtime);
    }
    // A launched process keeps quiet about the scenario's warnings: `plexus launch` said them once.
    scenario::log_warnings(sc, {}, !part_file.empty());
    // Each executable hosts what its declaration says. Its name, unless --service gives one, is
    // the one plexus launch would give it (launch_plan.hpp): the executable and its robots (a
    // plant's and sensors' robot) or its services, "plant_simulator r1", "localisation_observer
    // observer"; its heartbeats go to health/<that name> (docs/topics.md).
    std::string hosted_names;
    std::set<std::string> named;
    for (const auto& c : sc.components) {
      const std::string& n = c.component->name();
      const bool robot_part = c.kind == scenario::ComponentKind::plant || c.kind == scenario::ComponentKind::sensor;
      const std::string name = robot_part ? n.substr(0, n.find('/')) : n;
      if (named.insert(name).second) hosted_names += (hosted_names.empty() ? "" : ",") + name;
      if (const std::string why = hosting_error(service, c); !why.empty()) throw InputError(why);
    }
    if (sc.components.empty()) throw InputError(sc.file + ": no component to run");
    const std::vector<bool> hosted(sc.components.size(), true);

    const rt::ParticipantOptions po = net.participant(self + " " + hosted_names, self);
    const auto profiles = net.profiles();
    // Realtime with a priority: the DDS threads the participant starts (receive, events)
    // inherit it from this thread, so that the loop never waits on a delivery thread that
    // its own priority starves (docs/performance.md, "Priorities").
    if (realtime && (priority > 0 || cpu >= 0)) {
      rt::LoopOptions threads;
      threads.priority = priority;
      threads.cpu = cpu;
      (void)rt::apply_thread_settings(threads);
    }
    auto participant = rt::Participant::create(po);
    // Another process writing one of its topics: warned once, from a thread beside the loop.
    const service::ProducerMonitor producers(*participant, sc, po.name);
    if (realtime) {
      distributed::RealtimeOptions ro;
      ro.service = po.name;
      ro.loop.priority = priority;
      ro.loop.cpu = cpu;
      ro.wait_for_start = start_signal;
      if (app.count("--timeout")) ro.start_timeout_s = timeout;  // the longest wait for the start signal too
      distributed::RealtimeHost host(sc, hosted, *participant, profiles, ro);
      const auto r = host.run(g_stop);
      // The stop summary (docs/services.md): on stderr at any log level when the service runs
      // alone; under plexus launch, whose summary has these counts, at info.
      const std::string summary = fmt::format(
          "ran {} ticks: {} holds, {} stale and {} late input reads, {} refused samples, jitter p99 {:.1f} us, "
          "{} overruns, {} blind estimator steps; {} loop iterations, compute p99 {:.1f} us, "
          "{} estimator steps run after their tick, {} late samples dropped or bridged",
          r.ticks, r.holds, r.stale_inputs, r.late_inputs, r.rejected_inputs, r.loop.jitter_p99_us, r.loop.overruns,
          r.blind_steps, r.loop.iterations, r.loop.compute_p99_us, r.deferred_steps, r.dropped_late_samples);
      if (part_file.empty())
        std::fprintf(stderr, "%s: %s\n", po.name.c_str(), summary.c_str());
      else
        spdlog::info("{}", summary);
      return exit_within(0, kTeardownDeadlineS, self);  // armed before the participant is deleted
    }
    distributed::LockstepHost host(sc, hosted, *participant, profiles.get(profile),
                                   {.timeout_s = timeout, .service = po.name});
    const int64_t steps = host.run(g_stop);
    if (part_file.empty())
      std::fprintf(stderr, "%s: ran %lld steps\n", po.name.c_str(), static_cast<long long>(steps));
    else
      spdlog::info("ran {} steps", steps);
    return exit_within(0, kTeardownDeadlineS, self);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", self.c_str(), e.what());
    return kExitBadInput;
  } catch (const distributed::LockstepError& e) {
    std::fprintf(stderr, "%s: %s\n", self.c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {  // a DDS entity that cannot be created, for one
    std::fprintf(stderr, "%s: failed: %s\n", self.c_str(), e.what());
    return 1;
  }
}
