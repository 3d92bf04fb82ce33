// The end of a run, the same for `plexus sim` and both modes of `plexus launch`:
// evaluate the metrics, write the run folder, print the result.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plexus/evaluation/run_folder.hpp"
#include "plexus/scenario/scenario.hpp"
#include "plexus/scenario/signal_log.hpp"

namespace plexus::cli {

/// What a command adds to the common output.
struct RunSummary {
  std::string headline;  ///< first line of the text output
  nlohmann::ordered_json extra =
      nlohmann::ordered_json::object();  ///< merged into --json; also <run folder>/launch.json
  std::vector<std::string> lines;        ///< text lines after the metrics
};

/// The unit of each field of each IDL message type, as the wire description declares it
/// (common/distributed/src/wire_types.cpp): the units of the run folder's signals.json.
scenario::FieldUnits wire_field_units();

/// Evaluates the run, writes the run folder `dir` (from scenario::prepare_run_folder), prints
/// the metrics and digest (text, or one JSON object with `--json`), the run folder line unless
/// quiet, and every failed expectation. Returns 0 if every expectation holds, else 1.
int finish_run(const scenario::Scenario& sc, const scenario::RunLog& log, double wall_seconds,
               const std::filesystem::path& dir, bool json, bool quiet, const RunSummary& summary);

/// A run stopped by SIGINT or SIGTERM before its end: the run folder `dir` is marked
/// "interrupted (SIG...)" (no metrics: a partial run is not scored) and one line says so.
/// Returns the exit code, 128 + the signal (130 for Ctrl-C), as a shell reports it.
int interrupted_run(const std::string& command, int signal, const std::filesystem::path& dir, double wall_seconds);

/// Logs the scenario's warnings once, short, pointing at the run folder's summary.md for the
/// details (written there by finish_run).
void log_scenario_warnings(const scenario::Scenario& sc, const std::filesystem::path& dir);

/// `plexus report` (and `launch --report`): writes the plots, report.md and report.html of a run folder,
/// prints the metrics-against-expectations table (the paper comparison) and the files.
/// Returns the number of FAIL rows.
int print_report(const std::string& run_dir, bool to_stderr = false);

}  // namespace plexus::cli
