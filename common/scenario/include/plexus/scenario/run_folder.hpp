// The run folder `plexus sim` writes:
//
//   scenario.resolved.yaml   the scenario after --set, with every derived seed written in
//   signals/<signal>.csv     one file per signal ('/' in its name becomes '.'):
//                            header `t,step,<field>...`, one row per sample
//   series/<metric>.csv      the time series a metric summarises, if any: `t,<metric>`
//   metrics.json             {"digest": "...", "<metric>": value, ...}
//   summary.md               what ran, how fast, the metrics against the expectations
#pragma once

#include <filesystem>
#include <string>

#include "plexus/scenario/evaluation.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

/// `runs/<name>-<UTC yyyymmddThhmmssZ>` under the current directory.
std::filesystem::path default_run_folder(const std::string& scenario_name);

/// The file name a signal is stored under in signals/ (without directory).
std::string signal_file_name(const std::string& signal);

/// Writes the run folder (creating it); throws InputError if it cannot be written.
void write_run_folder(const std::filesystem::path& dir, const Scenario& scenario, const RunLog& log,
                      const Evaluation& evaluation, double wall_seconds);

}  // namespace plexus::scenario
