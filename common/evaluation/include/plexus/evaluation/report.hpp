// `plexus report RUN_DIR`: the figures and the comparison table of a run folder (run_folder.hpp).
//
// Writes, inside the run folder:
//   report.html                    the page to look at: the comparison table against the
//                                  papers and every figure inline (report_html.hpp)
//   report.md                      the same table and figures, as markdown
//   plots/paper<NNN>.<robot>.png   the papers' own figures, for each robot that has the
//                                  signals one of them needs (report_figures.hpp)
//   plots/<signal>.png             each signal against time, one panel per quantity and unit
//                                  (report_panels.hpp); the robot's true state dashed under
//                                  the same fields of its estimates and measurements
//   plots/<robot>.trajectory.png   y against x of every signal of the robot with x and y
//   plots/series.<metric>.png      the time series behind a metric
//   plots/data/*.csv               series the figures compute (tracking errors)
//   plots/report.gp                the gnuplot script (pngcairo terminal) drawing them all
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plexus::scenario {

struct Report {
  std::filesystem::path html;
  std::filesystem::path markdown;
  std::vector<std::filesystem::path> plots;
  std::string table;  ///< the metrics-against-expectations table (markdown), as in report.md
  int failed = 0;     ///< FAIL rows: expectations not met, or whose metric is missing
};

/// Throws InputError when `run_dir` is not a readable run folder, std::runtime_error
/// when gnuplot fails.
Report write_report(const std::filesystem::path& run_dir);

}  // namespace plexus::scenario
