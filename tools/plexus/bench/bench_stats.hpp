// `plexus bench`: a latency distribution as the run's JSON holds it (docs/qos-bench.md):
// nearest-rank percentiles, a CDF of about 60 points for the report, and the spread of the
// median between consecutive chunks of the run (the noise a cell measures of itself).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace plexus::cli::bench {

/// Samples (ns, one per line) from `path`, as microseconds shifted by -offset_us. Missing
/// file or empty path: none.
std::vector<double> read_samples_us(const std::string& path, double offset_us = 0);

/// {"count", "p50", "p90", "p99", "p999", "max", "cdf": [[us, fraction], ...]} of `us` (in
/// any order; sorted in a copy).
nlohmann::ordered_json distribution(const std::vector<double>& us);

/// max - min of the medians of `chunks` consecutive, equal parts of `us` (in time order);
/// 0 with fewer than 10 samples per chunk.
double median_spread(const std::vector<double>& us, int chunks = 3);

/// Nearest-rank quantile q in [0, 1] of sorted values; 0 when empty.
double quantile(const std::vector<double>& sorted, double q);

}  // namespace plexus::cli::bench
