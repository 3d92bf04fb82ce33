// The report of `plexus bench`: report.html, static HTML and CSS (no script, no network
// resource): the run's facts, the baseline's regressions, the summary table with the best
// cell of each size marked, the cells that did not run, the figures, loss and recovery.
#pragma once

#include <string>
#include <vector>

#include "bench/bench_report_data.hpp"
#include "bench/bench_report_figures.hpp"

namespace plexus::cli::bench_report_impl {

/// The page; its images are `figures` (plots/NAME.png).
std::string report_html(const json& run, const std::vector<Figure>& figures);

}  // namespace plexus::cli::bench_report_impl
