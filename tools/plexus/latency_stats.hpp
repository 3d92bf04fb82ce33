// Percentiles and PNG histograms (gnuplot) for `plexus latency`.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace plexus::cli {

struct Percentiles {
  std::size_t count = 0;
  double mean = 0, p50 = 0, p90 = 0, p99 = 0, max = 0;
};

/// Percentiles of `values` (sorted in place); nearest-rank.
Percentiles percentiles(std::vector<double>& values);

/// Percentiles of a histogram: counts[i] samples at value i (cyclictest's 1 us buckets).
Percentiles histogram_percentiles(const std::vector<double>& counts);

struct Series {
  std::string name;
  std::vector<double> values;  ///< samples (us), or bucket counts if `bucketed`
  bool bucketed = false;       ///< values[i] = count at i us
};

/// Writes `png` (and `png` + ".dat*"/".gp") with one histogram per series, x in us, log y.
/// Throws std::runtime_error if gnuplot is missing or fails.
void write_histogram_png(const std::string& png, const std::string& title, const std::vector<Series>& series);

/// "1.23" or "n/a" for ratio a/b.
std::string ratio_text(double a, double b);

/// {"count", "mean_us", "p50_us", "p90_us", "p99_us", "max_us"}.
nlohmann::ordered_json pct_json(const Percentiles& p);

/// Prints the table mean/p50/p90/p99/max of `a` (plexus) and `b` (`b_name`) and their ratio.
void print_compare(const char* what, const Percentiles& a, const Percentiles& b, const std::string& b_name,
                   bool b_has_p90);

/// Creates `dir` (and its parents) for --out; "" does nothing. InputError if it cannot.
void make_out_dir(const std::string& dir);

}  // namespace plexus::cli
