// The report of `plexus bench`: its figures, planned from the run alone (so the page can
// name them before they are drawn), and drawn with one gnuplot run (pngcairo).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_report_data.hpp"

namespace plexus::cli::bench_report_impl {

struct Curve {
  std::string title;  ///< its key entry; "" for none
  std::string data;   ///< its block of the figure's data file: rows "x y..."; "": the previous curve's
  std::string style;  ///< gnuplot "using ... with ..." of the block
};

struct Figure {
  std::string name;     ///< plots/NAME.png, plots/NAME.dat
  std::string section;  ///< "cdf", "throughput", "rate"
  std::string title, caption;
  std::string settings;  ///< gnuplot commands before its plot
  std::vector<Curve> curves;
};

/// Every figure of the run: a latency CDF per size and topology, throughput against size and
/// latency against rate per topology (those with data).
std::vector<Figure> plan_figures(const json& run);

/// Writes the figures' data files and plots/bench.gp into `dir`/plots, and runs gnuplot once.
void draw(const std::vector<Figure>& figures, const std::filesystem::path& dir);

}  // namespace plexus::cli::bench_report_impl
