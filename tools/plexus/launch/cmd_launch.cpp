// plexus launch SCENARIO [--host H] [--dds fast|cyclone] [--vendor PROCESS=VENDOR ...] [--set k=v ...] [--json]
//
// Runs a scenario distributed over DDS: the robots' plants and sensors in a plant_simulator
// process, each service (or `process` group) in its own process (launch_plan.hpp), children's
// logs relayed and collected (log_relay.hpp). Lockstep: the clock runs here and the run gives
// the digest of `plexus sim`, with steps_per_s. Realtime: restarts, fault injection and the
// latency record (realtime_run.hpp). Writes the same run folder and metrics as `plexus sim`.
// Children never outlive it. The command's stages: stages.hpp; its options: here.
#include <memory>

#include "command.hpp"
#include "launch_options.hpp"

namespace plexus::cli {

Command add_launch_command(CLI::App& root) {
  auto o = std::make_shared<LaunchOptions>();
  Command c;
  c.app = root.add_subcommand(
      "launch",
      "Run a scenario distributed over DDS, one process per service (lockstep, or realtime with clock.mode: realtime)");
  c.app->add_option("scenario", o->scenario, "Scenario file (YAML; required but with the internal --remote)");
  c.app->add_option("--host", o->host, "Start only the processes assigned to this host of the scenario");
  c.app->add_option("--dds", o->dds,
                    "DDS vendor of the clock and of every process without a `dds` key in the scenario (default: "
                    "dds.vendor, else fast)");
  c.app->add_option("--transport", o->transport,
                    "auto, udp or shm: between processes of one host (docs/runtime.md, Transports; default: "
                    "dds.transport, else auto)");
  c.app->add_option("--naming", o->naming,
                    "plexus or ros2: topic and type names on the wire, of every process (docs/ros2.md; default: "
                    "dds.naming, else plexus)");
  c.app
      ->add_option("--foxglove", o->foxglove,
                   "Also start foxglove_bridge on 127.0.0.1:PORT, on the clock's host, for the run (docs/viewing.md)")
      ->check(CLI::Range(1, 65535));
  c.app
      ->add_option("--monitor", o->monitor,
                   "Realtime: serve a live page of the run on http://127.0.0.1:PORT/ (processes, loops, a plot; "
                   "docs/viewing.md)")
      ->check(CLI::Range(1, 65535));
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
  c.app->add_flag("--strict", o->strict,
                  "Realtime: end the run (exit 2) when a loop of the scenario (loops:) cannot fit its timing budget");
  c.app->add_flag("--report", o->report,
                  "Then plot the run and print its metrics against the expectations (plexus report)");
  c.app->add_option(
      "--ssh-config", o->ssh_config,
      "Hosts reached over ssh (hosts.<h>.ssh): use this ssh configuration file (ssh -F; default ~/.ssh/config)");
  c.app->add_flag(
      "--allow-clock-offset", o->allow_clock_offset,
      "Realtime over ssh hosts: run even when a host's clock is beyond the offset bound (docs/distributed.md)");
  c.app->add_flag("--remote", o->remote, "Internal: the share of one host, started over ssh by plexus launch")
      ->group("");
  c.app
      ->add_option("--inject-clock-offset", o->clock_injections,
                   "Tests: HOST=SECONDS added to that host's clock readings in the offset exchange")
      ->group("");
  c.run = [o] { return run_launch(*o); };
  return c;
}

}  // namespace plexus::cli
