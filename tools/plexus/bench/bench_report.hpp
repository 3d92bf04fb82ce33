// The report of `plexus bench`: report.html, its gnuplot figures and cells.csv, from the
// run's run.json (schema version 1: "plexus_bench": 1).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace plexus::cli {

/// Writes OUT_DIR/report.html, OUT_DIR/plots/*.png (gnuplot, with the data files and
/// plots/bench.gp that redraws them) and OUT_DIR/cells.csv from a run; OUT_DIR/run.json too
/// if it is not there (the page links to it). Throws std::runtime_error on failure.
void write_bench_report(const nlohmann::ordered_json& run, const std::string& out_dir);

/// The CSV alone: a header row, then one row per cell and rate of an ok cell (per entry of
/// its "latency"), one row with an empty rate for a cell without entries (not_applicable,
/// failed). Fields of a missing or null member are empty.
std::string bench_csv(const nlohmann::ordered_json& run);

/// The page alone; its images are the files write_bench_report draws (plots/NAME.png).
std::string bench_report_html(const nlohmann::ordered_json& run);

}  // namespace plexus::cli
