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

#include "plexus/evaluation/evaluation.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::scenario {

/// `runs/<name>-<UTC yyyymmddThhmmssZ>` under the current directory.
std::filesystem::path default_run_folder(const std::string& scenario_name);

/// The file in a run folder that says how far the run got: "running", "complete" (it ran to
/// its end; its expectations may still have failed), "interrupted (SIGINT)", "failed: ...".
inline constexpr const char* kRunStatusFile = "status";

/// Creates the folder a run writes to, before the run starts. `out` (--out) if given: an
/// earlier plexus run folder there is emptied first (nothing of that run mixes into this
/// one's report); a non-empty folder that is not a run folder is refused (InputError).
/// Otherwise a new `runs/<name>-<UTC time><suffix>`, made unique with -2, -3, ... when runs
/// start in the same second. The folder is marked "running".
std::filesystem::path prepare_run_folder(const std::string& out, const std::string& scenario_name,
                                         const std::string& suffix = {});

/// Writes the run's status (see kRunStatusFile).
void mark_run_folder(const std::filesystem::path& dir, const std::string& status);

/// The status of a run folder ("complete" for one written before the status file existed;
/// empty if `dir` is not a run folder).
std::string run_folder_status(const std::filesystem::path& dir);

/// A folder a plexus run wrote (it has a status file, or the files every run folder has).
bool is_run_folder(const std::filesystem::path& dir);

/// The file name a signal is stored under in signals/ (without directory).
std::string signal_file_name(const std::string& signal);

/// The unit of a field of an IDL message type ("m", "rad/s"; "" for a dimensionless one),
/// or nullopt when the type or the field is unknown. The units are declared once, with the
/// wire description of each message type (plexus_distributed, wire_types.cpp); the run
/// folder writer takes them as a function so that this library does not depend on DDS.
using FieldUnits = std::function<std::optional<std::string>(const std::string& message, const std::string& field)>;

/// Writes the run folder (creating it) and marks it "complete"; throws InputError if it
/// cannot be written. Without `units`, signals.json gives every unit as null (not declared).
void write_run_folder(const std::filesystem::path& dir, const Scenario& scenario, const RunLog& log,
                      const Evaluation& evaluation, double wall_seconds, const FieldUnits& units = {});

}  // namespace plexus::scenario
