// plant_simulator / component_host: run a share of a scenario's components in lockstep
// over DDS. `plexus launch` starts these; they can also be started by hand on another
// machine with the same scenario file.
//
//   plant_simulator SCENARIO [--robots r1,r2] --dds fast --domain 7
//   component_host  SCENARIO --components tracker,observer --dds cyclone --domain 7
#include <sys/prctl.h>

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <set>
#include <sstream>

#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/distributed/lockstep.hpp"
#include "plexus/distributed/realtime.hpp"
#include "plexus/distributed/service_catalog.hpp"
#include "plexus/scenario/overrides.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

constexpr const char* kName = PLEXUS_SERVICE_NAME;
#ifdef PLEXUS_PLANT_SIMULATOR
constexpr const char* kAbout =
    "plant_simulator: the plants and sensors of a scenario's robots, over DDS (lockstep or realtime)";
#else
constexpr const char* kAbout =
    "plexus service: hosts the named components of a scenario over DDS (lockstep or realtime); "
    "see common/distributed/include/plexus/distributed/service_catalog.hpp for which types each service hosts";
#endif

std::set<std::string> split(const std::string& csv) {
  std::set<std::string> out;
  std::stringstream ss(csv);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.insert(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace plexus;
  CLI::App app{kAbout};
  std::string scenario_file, dds = "fast", qos_file, profile = "lockstep", log_level = "warn", selection, mode;
  int priority = 0, cpu = -1;
  std::string interface_address = "127.0.0.1", peers = "127.0.0.1";
  std::vector<std::string> sets;
  int domain = 0;
  double timeout = 10.0;
  app.add_option("scenario", scenario_file, "Scenario file")->required();
#ifdef PLEXUS_PLANT_SIMULATOR
  app.add_option("--robots", selection, "Comma-separated robots to simulate (default: all)");
#else
  app.add_option("--components", selection, "Comma-separated component names to host")->required();
#endif
  app.add_option("--set", sets, "Scenario override dotted.key=value (as plexus sim)");
  app.add_option("--dds", dds, "DDS vendor: fast or cyclone");
  app.add_option("--domain", domain, "DDS domain id");
  app.add_option("--qos-file", qos_file, "QoS profiles (default deploy/qos.yaml)");
  app.add_option("--profile", profile, "QoS profile of the lockstep topics");
  app.add_option("--timeout", timeout, "Lockstep: seconds to wait for one input before failing");
  app.add_option("--mode", mode, "lockstep or realtime (default: the scenario's clock mode)")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  app.add_option("--priority", priority, "Realtime: SCHED_FIFO priority (0: normal scheduling)");
  app.add_option("--cpu", cpu, "Realtime: pin the loop to this CPU");
  app.add_option("--interface", interface_address, "Address of the one interface DDS uses (default 127.0.0.1)");
  app.add_option("--peers", peers, "Comma-separated unicast discovery peers (default 127.0.0.1)");
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  }
  prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive the launcher
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging(kName, "", log_level);
    std::vector<scenario::Override> overrides;
    for (const auto& s : sets) overrides.push_back(scenario::parse_override(s));
    scenario::Scenario sc = scenario::load_scenario(scenario_file, overrides);

    const auto wanted = split(selection);
    std::vector<bool> hosted(sc.components.size(), false);
    std::set<std::string> found;
    for (std::size_t i = 0; i < sc.components.size(); ++i) {
      const auto& c = sc.components[i];
#ifdef PLEXUS_PLANT_SIMULATOR
      const bool physical = c.kind == scenario::ComponentKind::plant || c.kind == scenario::ComponentKind::sensor;
      const std::string robot = c.component->name().substr(0, c.component->name().find('/'));
      hosted[i] = physical && (wanted.empty() || wanted.count(robot));
      if (hosted[i]) found.insert(robot);
#else
      hosted[i] = wanted.count(c.component->name()) != 0;
      if (hosted[i]) found.insert(c.component->name());
      if (hosted[i] && std::string(kName) != "component_host" && distributed::executable_for(c.type) != kName)
        throw InputError(std::string("--components: '") + c.component->name() + "' is a " + c.type + ", which " + kName +
                         " does not host (it runs in " + distributed::executable_for(c.type) + ")");
#endif
    }
    for (const auto& w : wanted)
      if (!found.count(w)) throw InputError(std::string("--") + (kName[0] == 'p' ? "robots" : "components") + ": '" + w +
                                            "' is not in " + scenario_file);

    rt::ParticipantOptions po;
    po.vendor = rt::parse_vendor(dds);
    po.domain_id = domain;
    po.name = kName + std::string(selection.empty() ? "" : " " + selection);
    po.network.interface_address = interface_address;
    const auto peer_set = split(peers);
    po.network.peers.assign(peer_set.begin(), peer_set.end());
    const auto profiles = rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file);
    auto participant = rt::Participant::create(po);
    const bool realtime = mode.empty() ? sc.clock == scenario::ClockMode::realtime : mode == "realtime";
    if (realtime) {
      distributed::RealtimeOptions ro;
      ro.service = po.name;
      ro.loop.priority = priority;
      ro.loop.cpu = cpu;
      distributed::RealtimeHost host(sc, hosted, *participant, profiles, ro);
      const auto r = host.run(g_stop);
      spdlog::info("ran {} ticks: {} holds, {} stale and {} late input reads, {} refused samples, jitter p99 {:.1f} us, "
                   "{} overruns",
                   r.ticks, r.holds, r.stale_inputs, r.late_inputs, r.rejected_inputs, r.loop.jitter_p99_us, r.loop.overruns);
      return 0;
    }
    distributed::LockstepHost host(sc, hosted, *participant, profiles.get(profile), {.timeout_s = timeout});
    const int64_t steps = host.run(g_stop);
    spdlog::info("ran {} steps", steps);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return kExitBadInput;
  } catch (const distributed::LockstepError& e) {
    std::fprintf(stderr, "%s: %s\n", kName, e.what());
    return 1;
  } catch (const std::exception& e) {  // a DDS entity that cannot be created, for one
    std::fprintf(stderr, "%s: failed: %s\n", kName, e.what());
    return 1;
  }
}
