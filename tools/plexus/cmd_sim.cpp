// plexus sim SCENARIO [--set key=value ...] [--out DIR] [--json] [--quiet] [--seeds N]
//
// Runs a scenario in one process (no DDS), in lockstep, as fast as the machine goes;
// writes a run folder and prints the metrics and the digest. With --seeds N, runs it with
// N seeds and prints each metric's statistics over them (seed_sweep.hpp). Exit codes: 0 all
// expectations met (on the mean over the seeds with --seeds), 1 an expectation failed,
// 2 bad scenario or arguments.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/progress_bar.hpp"
#include "plexus/evaluation/run_folder.hpp"
#include "plexus/scenario/executor.hpp"
#include "plexus/scenario/registry.hpp"
#include "plexus/scenario/scenario.hpp"
#include "qos_names.hpp"
#include "run_result.hpp"
#include "seed_sweep.hpp"

namespace plexus::cli {
namespace {

struct SimOptions {
  std::string scenario;
  std::vector<std::string> sets;
  std::string out, qos_file;
  bool json = false;
  bool quiet = false;
  bool list = false;
  int seeds = 0;  ///< 0: one run
};

int list_types() {
  std::printf("component types:\n");
  for (const auto* t : scenario::component_types())
    std::printf("  %-22s %-10s %s\n", t->name.c_str(), scenario::to_string(t->kind), t->summary.c_str());
  std::printf("metric types:\n");
  for (const auto* t : scenario::metric_types()) std::printf("  %-22s %s\n", t->name.c_str(), t->summary.c_str());
  return 0;
}

int run_sim(const SimOptions& o) {
  if (o.list) return list_types();
  if (o.scenario.empty()) throw InputError("sim: a SCENARIO file is required (or --list)");
  std::vector<scenario::Override> overrides;
  for (const auto& s : o.sets) overrides.push_back(scenario::parse_override(s));
  scenario::Scenario sc = scenario::load_scenario(o.scenario, overrides);
  for (const auto& [robot, src] : sc.sources)
    throw InputError(src.where + ": robot " + robot + "'s source is " + scenario::to_string(src.type) +
                     "; `plexus sim` simulates every robot: run it with `plexus launch` (clock.mode: realtime)");
  // The QoS profiles it names, as `plexus launch` checks them (sim itself runs without DDS).
  const std::string qos_file = o.qos_file.empty() ? rt::default_qos_file() : o.qos_file;
  check_qos_names(sc, rt::QosProfiles::load(qos_file), qos_file);
  if (o.seeds > 0) return run_seed_sweep({o.scenario, overrides, o.seeds, o.out, o.json, o.quiet, wire_field_units()});

  const auto dir = scenario::prepare_run_folder(o.out, sc.name);
  log_scenario_warnings(sc, dir);
  scenario::ProgressBar bar(!o.quiet);
  const int64_t start = monotonic_ns();
  const scenario::RunLog log = scenario::run_scenario(sc, [&](int64_t k, int64_t n) { bar.update(k, n); });
  const double wall = static_cast<double>(monotonic_ns() - start) * 1e-9;
  bar.finish();

  char headline[256];
  std::snprintf(headline, sizeof headline, "scenario %s: %lld steps, %.3g s simulated in %.3g s", sc.name.c_str(),
                static_cast<long long>(sc.steps), sc.duration, wall);
  return finish_run(sc, log, wall, dir, o.json, o.quiet, {headline, nlohmann::ordered_json::object(), {}});
}

}  // namespace

Command add_sim_command(CLI::App& root) {
  auto opts = std::make_shared<SimOptions>();
  Command c;
  c.app =
      root.add_subcommand("sim", "Run a scenario in one process (no DDS), deterministically, faster than real time");
  c.app->add_option("scenario", opts->scenario, "Scenario file (YAML, see docs/scenarios.md)");
  c.app->add_option("--set", opts->sets, "Override a scenario value: dotted.key=value (repeatable)")
      ->allow_extra_args(false);
  c.app->add_option("-o,--out", opts->out, "Run folder (default runs/<scenario>-<UTC time>)");
  c.app->add_option("--qos-file", opts->qos_file,
                    "QoS profiles the scenario's `qos` keys name (default deploy/qos.yaml)");
  c.app->add_flag("--json", opts->json, "Print the metrics as one JSON object on stdout");
  c.app->add_flag("--quiet,-q", opts->quiet, "No progress bar, no run folder line");
  c.app
      ->add_option("--seeds", opts->seeds,
                   "Run with N seeds (the scenario's seed and the next N-1) and print each metric's mean, std, "
                   "standard error, t, min and max; expectations are checked on the mean")
      ->check(CLI::Range(1, 10000));
  c.app->add_flag("--list", opts->list, "List the registered component and metric types");
  c.run = [opts] { return run_sim(*opts); };
  return c;
}

}  // namespace plexus::cli
