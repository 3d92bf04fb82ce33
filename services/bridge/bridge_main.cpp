// The one main() of the hardware bridges, built twice (PLEXUS_BRIDGE_KIND):
//   serial_bridge: the device on a tty (--device, --baud)
//   udp_bridge:    the device on UDP (--bind, --peer)
//
// On its own, from a robot section (the plant and sensors it stands in for):
//   serial_bridge --robot r1 --params deploy/params/unicycle_robot.yaml --device /dev/ttyUSB0 --baud 1000000
//   udp_bridge --robot r1 --params deploy/params/unicycle_robot.yaml --bind 127.0.0.1:47001 --peer 127.0.0.1:47002
// Under `plexus launch`: --part FILE, the robot's section with its `source:` (docs/bridges.md).
// Runs until SIGINT/SIGTERM, then sends a last STOP frame, prints one JSON line with its
// counters on stdout and exits 0. Bad parameters: one line naming where, exit 2.
#include <sys/prctl.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>

#include "bridge.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/base/teardown_deadline.hpp"
#include "plexus/link/serial_port.hpp"
#include "plexus/link/udp_socket.hpp"
#include "plexus/runtime/periodic_loop.hpp"
#include "plexus/scenario/overrides.hpp"
#include "plexus/service/dds_options.hpp"
#include "plexus/service/producer_monitor.hpp"
#include "plexus/service/standalone.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

constexpr std::string_view kName = PLEXUS_BRIDGE_KIND;
constexpr bool kSerial = kName == "serial_bridge";

/// The link's counters as the exit line shows them: LinkStatus's members (generated), with
/// `up` in place of the state enum.
nlohmann::ordered_json link_json(const plexus::msg::LinkStatus& s) {
  nlohmann::ordered_json j{{"up", s.state() == plexus::msg::LINK_UP}};
  const nlohmann::ordered_json members = plexus::msg::to_json(s);
  for (const auto& [key, value] : members.items())
    if (key != "state") j[key] = value;
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace plexus;
  const std::string name(kName);
  CLI::App app{name + ": one robot's device on " + (kSerial ? "a serial line" : "UDP") +
               ", on the robot's typed topics in place of plant_simulator (docs/bridges.md)"};
  app.set_version_flag("--version", std::string(name) + " " + PLEXUS_VERSION);
  std::string part_file, log_level = "info", mode = "realtime";
  scenario::ServiceDdsOptions net;
  std::string device, bind, peer;
  long baud = 0;
  int priority = 0, cpu = -1;
  double link_timeout = 0, retry = 0, timeout = 0, time_sync_hz = 0;
  bool device_time = false, cycle_sync = false;
  std::vector<std::string> sets;
  bool start_signal = false;
  scenario::StandaloneSpec alone;
  alone.program = name;
  alone.robot_section = true;
  alone.command_rate_hz = scenario::kDefaultCommandRateHz;  // --input-rate cmd=HZ overrides
  app.add_option("--part", part_file, "The robot's part of a scenario, with its source (written by plexus launch)");
  app.add_option("--robot", alone.robot, "Robot whose topics it serves (default r1)");
  app.add_option("--params", alone.params_file, "YAML robot section: the plant and sensors it stands in for");
  app.add_option("--step", alone.step, "Base step in s (default 0.001)")->check(positive("s"));
  app.add_option("--input-rate", alone.input_rates, "cmd=HZ: the command's rate (default 100); stale after 3 periods");
  app.add_option("--set", sets, "Parameter override key=value");
  if (kSerial) {
    app.add_option("--device", device, "Serial device path (alone: required)");
    app.add_option("--baud", baud, "115200 .. 1000000 (default 1000000)");
    app.add_option("--retry", retry, "Seconds between attempts to open an absent device (default 0.5)");
  } else {
    app.add_option("--bind", bind, "ADDR:PORT the bridge receives on (alone: required)");
    app.add_option("--peer", peer, "ADDR:PORT of the device (alone: required)");
  }
  app.add_option("--link-timeout", link_timeout, "Seconds without a valid frame before the link is down (default 0.5)");
  app.add_flag("--device-time", device_time,
               "The device stamps its samples: map its clock to the host's by two-way exchanges (docs/bridges.md)");
  app.add_option("--time-sync-hz", time_sync_hz, "With --device-time: exchanges per second, 1 .. 200 (default 50)");
  app.add_flag("--cycle-sync", cycle_sync,
               "With --device-time: send the device the run's cycle in its clock, to step on (docs/bridges.md)");
  net.add_to(app);
  app.add_option("--mode", mode, "realtime only (a bridge follows its device's clock)")
      ->check(CLI::IsMember({"realtime", "lockstep"}));
  app.add_flag("--start-signal", start_signal,
               "Started by plexus launch: a bridge starts at once; the run's cycle (--cycle-sync) is its start's");
  app.add_option("--timeout", timeout, "Accepted for plexus launch (lockstep only)");
  app.add_option("--priority", priority, "Realtime: SCHED_FIFO priority of its threads, 1 .. 99 (0: normal scheduling)")
      ->check(fifo_priority());
  app.add_option("--cpu", cpu, "Realtime: pin its threads to this CPU (0, 1, ...)")->check(cpu_index());
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error, critical or off");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return parse_error_exit(app, e, name);
  }
  if (!part_file.empty()) prctl(PR_SET_PDEATHSIG, SIGTERM);  // under the launcher: never outlive it
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    init_logging(name.c_str(), "", log_level);
    if (mode != "realtime")
      throw InputError("--mode " + mode + ": a bridge runs in realtime only (its device keeps time)");
    scenario::Scenario sc;
    if (!part_file.empty()) {
      if (!device.empty() || baud || !bind.empty() || !peer.empty() || retry > 0 || link_timeout > 0 || device_time ||
          time_sync_hz > 0 || cycle_sync)
        throw InputError(
            "--part: the link comes from the part's `source:`; drop "
            "--device/--baud/--bind/--peer/--retry/--link-timeout/--device-time/--time-sync-hz/--cycle-sync");
      std::vector<scenario::Override> overrides;
      for (const auto& s : sets) overrides.push_back(scenario::parse_override(s));
      sc = scenario::load_scenario(part_file, overrides, {.partial = true});
    } else {
      YAML::Node src(YAML::NodeType::Map);
      src["type"] = name;
      // Options are checked here so that errors name the option, not a key it became.
      std::string error;
      link::UdpEndpoint endpoint;
      if (baud && !link::supported_baud(baud))
        throw InputError("--baud " + std::to_string(baud) +
                         ": expected 115200, 230400, 460800, 500000, 576000, 921600 or 1000000");
      if (!bind.empty() && !link::parse_endpoint(bind, "--bind", endpoint, error)) throw InputError(error);
      if (!peer.empty() && !link::parse_endpoint(peer, "--peer", endpoint, error)) throw InputError(error);
      if (retry < 0 || link_timeout < 0) throw InputError("--retry and --link-timeout: expected seconds > 0");
      if (kSerial) {
        if (device.empty()) throw InputError("--device: required (the serial device path)");
        src["device"] = device;
        if (baud) src["baud"] = baud;
        if (retry > 0) src["retry"] = retry;
      } else {
        if (bind.empty() || peer.empty()) throw InputError("--bind and --peer: required (ADDR:PORT each)");
        src["bind"] = bind;
        src["peer"] = peer;
      }
      if (link_timeout > 0) src["link_timeout"] = link_timeout;
      // The link comes from the options; what the device speaks (its own frames, its
      // clock) from the robot section's `source`, if it has one.
      try {
        const YAML::Node own = alone.params_file.empty() ? YAML::Node() : YAML::LoadFile(alone.params_file)["source"];
        if (own && own.IsMap())
          for (const char* key : {"frames", "device_time", "time_sync_hz", "cycle_sync"})
            if (own[key]) src[key] = own[key];
      } catch (const YAML::Exception&) {
        // load_standalone reports the file's error with its line
      }
      if (device_time) src["device_time"] = true;
      if (app.count("--time-sync-hz")) src["time_sync_hz"] = time_sync_hz;
      if (cycle_sync) src["cycle_sync"] = true;
      alone.extra = YAML::Node(YAML::NodeType::Map);
      alone.extra["source"] = src;
      sc = scenario::load_standalone(alone, sets, true);
    }
    // A launched process keeps quiet about the scenario's warnings: `plexus launch` said them once.
    scenario::log_warnings(sc, {}, !part_file.empty());
    if (sc.sources.size() != 1)
      throw InputError(sc.file + ": a bridge serves exactly one robot whose `source` is " + name);
    const auto& [robot, src] = *sc.sources.begin();
    if (scenario::to_string(src.type) != name)
      throw InputError(src.where + ": robot " + robot + "'s source is " + scenario::to_string(src.type) + ", not " +
                       name);
    auto link = kSerial ? bridge::serial_link(src.device, src.baud) : bridge::udp_link(src.bind, src.peer, src.where);

    const rt::ParticipantOptions po = net.participant(name + " " + robot, name);
    const auto profiles = net.profiles();
    // Its threads' priority and CPU before the participant: the DDS threads inherit them, as
    // the bridge's command and I/O threads do (docs/performance.md, "Priorities").
    if (priority > 0 || cpu >= 0) {
      rt::LoopOptions threads;
      threads.priority = priority;
      threads.cpu = cpu;
      (void)rt::apply_thread_settings(threads);  // a refusal is warned, and the bridge runs without it
    }
    auto participant = rt::Participant::create(po);
    // A plant simulator of the same robot left running would interleave with the device: warned.
    const service::ProducerMonitor producers(*participant, sc, po.name);
    bridge::Bridge b(sc, *participant, profiles, std::move(link),
                     {.service = po.name,
                      .link_timeout_s = src.link_timeout_s,
                      .retry_s = src.retry_s,
                      .device_time = src.device_time,
                      .time_sync_hz = src.time_sync_hz,
                      .cycle_sync = src.cycle_sync,
                      .start_signal = start_signal});
    const auto r = b.run(g_stop);
    nlohmann::ordered_json j{{"service", po.name},
                             {"run_s", r.run_s},
                             {"commands_forwarded", r.commands_forwarded},
                             {"commands_refused", r.commands_refused},
                             {"link", link_json(r.link)}};
    std::printf("%s\n", j.dump().c_str());
    std::fflush(stdout);
    return exit_within(0, kTeardownDeadlineS, name);  // armed before the bridge and participant go
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: failed: %s\n", name.c_str(), e.what());
    return 1;
  }
}
