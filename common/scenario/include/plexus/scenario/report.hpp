// `plexus report RUN_DIR`: plots and a metrics table for a run folder (run_folder.hpp).
//
// Writes, inside the run folder:
//   plots/<signal>.png             each field of a signal against time; for a signal of a
//                                  robot other than its state, the state's fields of the
//                                  same name are overlaid dashed (estimates vs truth)
//   plots/<robot>.trajectory.png   y against x of the robot's state and of every other
//                                  signal of that robot with x and y (trajectory vs
//                                  reference, estimates and measurements)
//   plots/series.<metric>.png      the time series behind a metric (errors vs time)
//   plots/report.gp                the gnuplot script (pngcairo terminal)
//   report.md                      metrics against the scenario's expectations, and the plots
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plexus::scenario {

struct Report {
  std::filesystem::path markdown;
  std::vector<std::filesystem::path> plots;
  std::string table;  ///< the metrics-against-expectations table (markdown), as in report.md
  int failed = 0;     ///< FAIL rows: expectations not met, or whose metric is missing
};

/// Throws InputError when `run_dir` is not a readable run folder, std::runtime_error
/// when gnuplot fails.
Report write_report(const std::filesystem::path& run_dir);

}  // namespace plexus::scenario
