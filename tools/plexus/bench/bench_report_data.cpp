#include "bench/bench_report_data.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "plexus/scenario/format.hpp"

namespace plexus::cli::bench_report_impl {
using plexus::scenario::format_number;

// ---- Reading run.json: of a failed or not_applicable cell any measure may be missing or null.

/// The member at `path` of `j`, or nullptr if a step is missing, null or not an object.
const json* member(const json& j, const Path& path) {
  const json* at = &j;
  for (const char* key : path) {
    if (!at->is_object()) return nullptr;
    const auto it = at->find(key);
    if (it == at->end() || it->is_null()) return nullptr;
    at = &*it;
  }
  return at;
}

std::optional<double> number(const json& j, const Path& path) {
  const json* v = member(j, path);
  if (!v || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

/// A scalar as text (integers as integers); an array or object as compact JSON.
std::string scalar_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return format_number(v.get<double>());
  if (v.is_null()) return "";
  return v.dump();
}

std::string text(const json& j, const Path& path) {
  const json* v = member(j, path);
  return v ? scalar_text(*v) : "";
}

/// A value as the page shows it: 4 significant digits, but large counts in full.
std::string shown(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, std::fabs(v) >= 1e4 ? "%.0f" : "%.4g", v);
  return buf;
}

std::string size_text(double bytes) {
  const auto b = static_cast<long long>(bytes);
  if (b >= (1 << 20) && b % (1 << 20) == 0) return std::to_string(b >> 20) + " MiB";
  if (b >= 1024 && b % 1024 == 0) return std::to_string(b >> 10) + " KiB";
  return shown(bytes) + " B";
}

std::string rate_text(double hz) { return hz > 0 ? shown(hz) + " Hz" : "unpaced"; }

std::vector<const json*> cells_of(const json& run) {
  std::vector<const json*> cells;
  if (const json* c = member(run, {"cells"}); c && c->is_array())
    for (const auto& cell : *c)
      if (cell.is_object()) cells.push_back(&cell);
  return cells;
}

bool is_ok(const json& cell) { return text(cell, {"status"}) == "ok"; }

/// Pair, transport and profile: the cells that a figure's curve joins.
std::string group_of(const json& cell) {
  return text(cell, {"pair"}) + "/" + text(cell, {"transport"}) + "/" + text(cell, {"profile"});
}

/// The rate the summary and the CDFs read latencies at: the matrix's first paced rate, the same
/// load for every cell (unpaced, each pair sets its own pace); the first rate if none is paced.
std::optional<double> summary_rate(const json& run) {
  const json* rates = member(run, {"matrix", "rates_hz"});
  if (!rates || !rates->is_array()) return std::nullopt;
  std::optional<double> first;
  for (const auto& r : *rates) {
    if (!r.is_number()) continue;
    const double hz = r.get<double>();
    if (hz > 0) return hz;
    if (!first) first = hz;
  }
  return first;
}

/// The cell's latency entry at `rate`, or nullptr.
const json* latency_at(const json& cell, std::optional<double> rate) {
  const json* entries = member(cell, {"latency"});
  if (!rate || !entries || !entries->is_array()) return nullptr;
  for (const auto& e : *entries)
    if (e.is_object() && number(e, {"rate_hz"}) == rate) return &e;
  return nullptr;
}

std::optional<double> entry_number(const json* entry, const Path& path) {
  return entry ? number(*entry, path) : std::nullopt;
}

std::optional<double> lost_percent(const json* entry) {
  const auto lost = entry_number(entry, {"lost"}), sent = entry_number(entry, {"sent"});
  if (!lost || !sent || !(*sent > 0)) return std::nullopt;
  return 100.0 * *lost / *sent;
}

void write_file(const std::filesystem::path& path, const std::string& content) {
  std::ofstream f(path, std::ios::binary);
  f << content;
  f.close();
  if (!f) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace plexus::cli::bench_report_impl
