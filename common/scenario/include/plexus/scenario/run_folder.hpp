// The run folder `plexus sim` writes:
//
//   scenario.resolved.yaml   the scenario after --set, with every derived seed written in
//   signals/<signal>.csv     one file per signal ('/' in its name becomes '.'):
//                            header `t,step,<field>...`, one row per sample
//   series/<metric>.csv      the time series a metric summarises, if any: `t,<metric>`
//   signals.json             what each signal is: {"<signal>": {"file", "producer", "message",
//                            "units": {"<field>": "m" | "" (dimensionless) | null (not declared)}}}
//   metrics.json             {"digest": "...", "<metric>": value, ...}
//   summary.md               what ran, how fast, the metrics against the expectations
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "plexus/scenario/evaluation.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

/// `runs/<name>-<UTC yyyymmddThhmmssZ>` under the current directory.
std::filesystem::path default_run_folder(const std::string& scenario_name);

/// The file name a signal is stored under in signals/ (without directory).
std::string signal_file_name(const std::string& signal);

/// The unit of a field of an IDL message type ("m", "rad/s"; "" for a dimensionless one),
/// or nullopt when the type or the field is unknown. The units are declared once, with the
/// wire description of each message type (plexus_distributed, wire_types.cpp); the run
/// folder writer takes them as a function so that this library does not depend on DDS.
using FieldUnits = std::function<std::optional<std::string>(const std::string& message, const std::string& field)>;

/// Writes the run folder (creating it); throws InputError if it cannot be written. Without
/// `units`, signals.json gives every unit as null (not declared).
void write_run_folder(const std::filesystem::path& dir, const Scenario& scenario, const RunLog& log,
                      const Evaluation& evaluation, double wall_seconds, const FieldUnits& units = {});

}  // namespace plexus::scenario
