// The report of `plexus bench`: cells.csv, one row per cell and rate (RFC 4180).
#pragma once

#include <string>

#include "bench/bench_report_data.hpp"

namespace plexus::cli::bench_report_impl {

/// A header row, then one row per latency entry of each cell, or one with an empty rate for
/// a cell without entries; a missing or null member is an empty field.
std::string csv_of(const json& run);

}  // namespace plexus::cli::bench_report_impl
