// The report of `plexus bench` (bench_report.hpp), reading run.json: of a cell that did not
// run any member may be missing or null, so each read says what it found. Shared by the page,
// its figures and the CSV; in a namespace of their own, as a unity build puts several .cpp
// files in one translation unit.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace plexus::cli::bench_report_impl {

using json = nlohmann::ordered_json;
using Path = std::vector<const char*>;

/// The member at `path` of `j`, or nullptr if a step is missing, null or not an object.
const json* member(const json& j, const Path& path);
/// The number at `path`, if there is one.
std::optional<double> number(const json& j, const Path& path);
/// A scalar as text (integers as integers); an array or object as compact JSON.
std::string scalar_text(const json& v);
/// The member at `path` as text ("" if none).
std::string text(const json& j, const Path& path);
/// A value as the page shows it: 4 significant digits, but large counts in full.
std::string shown(double v);
/// "64 B", "4 KiB", "1 MiB".
std::string size_text(double bytes);
/// "1000 Hz", or "unpaced" for 0.
std::string rate_text(double hz);
/// The run's cells that are objects.
std::vector<const json*> cells_of(const json& run);
bool is_ok(const json& cell);
/// Pair, transport and profile: the cells that a figure's curve joins.
std::string group_of(const json& cell);
/// The rate the summary and the CDFs read latencies at: the matrix's first paced rate, the
/// same load for every cell; the first rate if none is paced.
std::optional<double> summary_rate(const json& run);
/// The cell's latency entry at `rate`, or nullptr.
const json* latency_at(const json& cell, std::optional<double> rate);
std::optional<double> entry_number(const json* entry, const Path& path);
/// lost / sent of a latency entry, in %.
std::optional<double> lost_percent(const json* entry);

/// Writes a file whole; std::runtime_error naming it if it cannot.
void write_file(const std::filesystem::path& path, const std::string& content);

}  // namespace plexus::cli::bench_report_impl
