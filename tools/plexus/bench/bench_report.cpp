#include "bench/bench_report.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "external_program.hpp"
#include "plexus/base/html_escape.hpp"

// Unity builds put several .cpp files in one translation unit: the helpers live in their own
// namespace so that they cannot clash with another file's (write_file, esc, json...).
namespace plexus::cli::bench_report_impl {
namespace {

using json = nlohmann::ordered_json;
using Path = std::vector<const char*>;

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

/// The shortest text that reads back as the same double ("60.1", not "60.100000000000001").
std::string shortest(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "";
}

/// A scalar as text (integers as integers); an array or object as compact JSON.
std::string scalar_text(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return shortest(v.get<double>());
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

// ---- HTML.

std::string esc(const std::string& s) { return html_escape(s); }

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 0 auto; max-width: 1280px; padding: 0 1.5em 3em; color: #1a1a1a; }
h1 { margin-top: 1em; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 2em; }
code { font-size: 95%; }
.wide { overflow-x: auto; }
table.facts { border-collapse: collapse; margin: 1em 0; color: #333; }
table.facts th, table.facts td { padding: .15em .8em .15em 0; text-align: left; vertical-align: top; }
table.facts th { font-weight: normal; color: #666; white-space: nowrap; }
table.bench { border-collapse: collapse; margin: 1em 0; }
table.bench th, table.bench td { border: 1px solid #bbb; padding: .25em .6em; }
table.bench th { background: #eee; text-align: center; }
table.bench td { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.bench td.key { text-align: left; }
table.bench td.text { text-align: left; white-space: normal; }
table.bench td.na { color: #999; text-align: center; }
table.bench tr.size-start td { border-top: 2px solid #555; }
#summary { font-size: 90%; }
#summary th, #summary td { padding: .2em .45em; }
.best { font-weight: bold; background: #d8f0d8; color: #145214; }
tr.failed td.status { color: #8a1010; font-weight: bold; }
tr.not_applicable td.status { color: #666; }
nav ul { columns: 3; }
figure { margin: 1.5em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { color: #333; margin-top: .3em; }
figcaption b { display: block; }
)";

/// A measure of the summary table. Better is lower, or higher if `higher_is_better`.
struct Measure {
  std::string group, name;
  bool higher_is_better;
  std::function<std::optional<double>(const json& cell, const json* entry)> value;
};

std::vector<Measure> summary_measures(const std::string& at) {
  const auto cell_value = [](Path path) { return [path](const json& c, const json*) { return number(c, path); }; };
  const auto entry_value = [](Path path) {
    return [path](const json&, const json* e) { return entry_number(e, path); };
  };
  const std::string lat = "latency at " + at + " (us)";
  return {
      {lat, "one-way p50", false, entry_value({"one_way_us", "p50"})},
      {lat, "one-way p99", false, entry_value({"one_way_us", "p99"})},
      {lat, "one-way p99.9", false, entry_value({"one_way_us", "p999"})},
      {lat, "round-trip p50", false, entry_value({"round_trip_us", "p50"})},
      // The noise the cell measured of itself (docs/qos-bench.md): what --baseline allows for.
      {lat, "one-way p50 spread", false, cell_value({"spread", "one_way_p50_us"})},
      {"pings at " + at, "lost %", false, [](const json&, const json* e) { return lost_percent(e); }},
      {"pings at " + at, "late", false, entry_value({"late"})},
      {"throughput", "samples/s", true, cell_value({"throughput", "samples_per_s"})},
      {"throughput", "MB/s", true, cell_value({"throughput", "mb_per_s"})},
      {"CPU at " + at + " (% of a core)", "writer", false, cell_value({"cpu_percent", "writer"})},
      {"CPU at " + at + " (% of a core)", "reader", false, cell_value({"cpu_percent", "reader"})},
      {"vs vendor tool", "round-trip p50 ratio", false, cell_value({"ratio", "round_trip_p50"})},
  };
}

using Values = std::vector<std::vector<std::optional<double>>>;  // [row][measure]

/// best[row][measure]: the row's value is the best of its column among the rows of the same
/// payload size (ties all marked). A column where every row of a size has the same value has
/// no mark there: nothing stands out.
std::vector<std::vector<bool>> best_marks(const std::vector<const json*>& rows, const Values& values,
                                          const std::vector<Measure>& measures) {
  std::vector<std::vector<bool>> best(rows.size(), std::vector<bool>(measures.size(), false));
  for (std::size_t m = 0; m < measures.size(); ++m) {
    std::map<double, std::pair<double, double>> range;  // size -> (lowest, highest)
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const auto v = values[r][m];
      if (!v) continue;
      const double size = number(*rows[r], {"size"}).value_or(-1);
      auto [it, added] = range.try_emplace(size, *v, *v);
      it->second = {std::min(it->second.first, *v), std::max(it->second.second, *v)};
    }
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const auto v = values[r][m];
      if (!v) continue;
      const auto [low, high] = range.at(number(*rows[r], {"size"}).value_or(-1));
      best[r][m] = low != high && *v == (measures[m].higher_is_better ? high : low);
    }
  }
  return best;
}

/// The ok cells, by payload size (the groups the best marks compare), in run order within one.
std::vector<const json*> summary_rows(const json& run) {
  std::vector<const json*> rows;
  for (const json* c : cells_of(run))
    if (is_ok(*c)) rows.push_back(c);
  std::stable_sort(rows.begin(), rows.end(), [](const json* a, const json* b) {
    return number(*a, {"size"}).value_or(INFINITY) < number(*b, {"size"}).value_or(INFINITY);
  });
  return rows;
}

void write_facts(std::ostream& html, const json& run) {
  const auto list = [&](const Path& path, const char* sep) {
    const json* v = member(run, path);
    if (!v || !v->is_array()) return v ? scalar_text(*v) : std::string("?");
    std::string s;
    for (const auto& x : *v) s += (s.empty() ? "" : sep) + scalar_text(x);
    return s;
  };
  const auto fact = [&](const std::string& name, const std::string& value) {
    html << "<tr><th>" << esc(name) << "</th><td>" << value << "</td></tr>\n";
  };
  const auto machine = [&](const char* key, const std::string& before = "", const std::string& after = "") {
    const std::string v = text(run, {"machine", key});
    return v.empty() ? v : before + v + after;
  };
  const auto join = [](std::vector<std::string> parts) {  // the non-empty ones, comma-separated
    std::string s;
    for (const auto& p : parts)
      if (!p.empty()) s += (s.empty() ? "" : ", ") + p;
    return s.empty() ? std::string("?") : s;
  };
  html << "<table class=\"facts\">\n";
  fact("command", "<code>" + esc(text(run, {"command"})) + "</code>");
  fact("started", esc(text(run, {"started_utc"})));
  const auto duration = number(run, {"duration_s"});
  fact("duration", duration ? esc(shown(*duration)) + " s" : "?");
  fact("machine", esc(join({machine("hostname"), machine("cpu_model"), machine("cpus", "", " CPUs"),
                            machine("memory_mb", "", " MB"), machine("kernel", "kernel ")})));
  fact("load (1, 5, 15 min)",
       "before " + esc(list({"machine", "load_before"}, " ")) + ", after " + esc(list({"machine", "load_after"}, " ")));
  fact("versions", esc(join({machine("plexus_version", "plexus "), machine("fastdds_version", "Fast DDS "),
                             machine("cyclonedds_version", "Cyclone DDS ")})));
  fact("matrix",
       esc("pairs " + list({"matrix", "pairs"}, ", ") + "; transports " + list({"matrix", "transports"}, ", ") +
           "; profiles " + list({"matrix", "profiles"}, ", ") + "; sizes " + list({"matrix", "sizes"}, ", ") +
           " B; rates " + list({"matrix", "rates_hz"}, ", ") + " Hz (0: unpaced); topologies " +
           list({"matrix", "topologies"}, ", ") + "; link loss " + text(run, {"matrix", "loss_percent"}) +
           " % (two_ns); " + text(run, {"matrix", "seconds_per_phase"}) + " s per phase; repeats " +
           text(run, {"matrix", "repeats"})));
  std::map<std::string, int> statuses;
  for (const json* c : cells_of(run)) ++statuses[text(*c, {"status"})];
  std::string counts;
  for (const auto& [status, n] : statuses) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  fact("cells", esc(std::to_string(cells_of(run).size()) + (counts.empty() ? "" : ": " + counts)));
  html << "</table>\n";
}

void write_summary(std::ostream& html, const json& run) {
  const auto rate = summary_rate(run);
  const std::string at = rate ? rate_text(*rate) : "?";
  const auto measures = summary_measures(at);
  const auto rows = summary_rows(run);
  Values values;
  for (const json* c : rows) {
    const json* entry = latency_at(*c, rate);
    auto& v = values.emplace_back();
    for (const auto& m : measures) v.push_back(m.value(*c, entry));
  }
  const auto best = best_marks(rows, values, measures);

  html << "<p>One row per cell that ran. Latencies, lost and late pings at " << esc(at)
       << ", the matrix's first paced rate, and the CPU of each end at that rate (% of one core); throughput: what "
          "arrived in the cell's throughput phase; spread: the range of the one-way p50 between chunks of the phase "
          "and between repeats (the noise the cell measured of itself). "
          "<span class=\"best\">Bold on green</span>: the best value of its column among the cells of the same "
          "payload size (lowest latency, loss, late, CPU and ratio; highest throughput); ties are all marked, and a "
          "column in which every cell of a size has the same value has no mark for that size. A thick line starts "
          "each size. The ratio is plexus' round-trip p50 over the vendor tool's (below 1: plexus is faster); "
          "<i>-</i>: not measured.</p>\n";
  html << "<div class=\"wide\"><table class=\"bench\" id=\"summary\">\n<thead><tr><th rowspan=\"2\">pair</th>"
          "<th rowspan=\"2\">transport</th><th rowspan=\"2\">profile</th><th rowspan=\"2\">size</th>"
          "<th rowspan=\"2\">topology</th>";
  for (std::size_t m = 0; m < measures.size();) {  // one header per run of measures of a group
    std::size_t n = 1;
    while (m + n < measures.size() && measures[m + n].group == measures[m].group) ++n;
    html << "<th colspan=\"" << n << "\">" << esc(measures[m].group) << "</th>";
    m += n;
  }
  html << "</tr>\n<tr>";
  for (const auto& m : measures) html << "<th>" << esc(m.name) << "</th>";
  html << "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const json& c = *rows[r];
    const bool size_start = r == 0 || number(c, {"size"}) != number(*rows[r - 1], {"size"});
    const auto size = number(c, {"size"});
    const auto link_loss = number(c, {"loss_percent"});
    html << "<tr data-cell=\"" << esc(text(c, {"id"})) << "\"" << (size_start ? " class=\"size-start\"" : "")
         << "><td class=\"key\">" << esc(text(c, {"pair"})) << "</td><td class=\"key\">" << esc(text(c, {"transport"}))
         << "</td><td class=\"key\">" << esc(text(c, {"profile"})) << " <small>" << esc(text(c, {"reliability"}))
         << "</small></td><td class=\"key\">" << (size ? esc(size_text(*size)) : "?") << "</td><td class=\"key\">"
         << esc(text(c, {"topology"}))
         << (link_loss && *link_loss > 0 ? " <small>loss " + esc(shown(*link_loss)) + " %</small>" : "") << "</td>";
    for (std::size_t m = 0; m < measures.size(); ++m) {
      if (!values[r][m])
        html << "<td class=\"na\">-</td>";
      else
        html << (best[r][m] ? "<td class=\"best\">" : "<td>") << esc(shown(*values[r][m])) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</tbody>\n</table></div>\n";
  std::vector<std::string> tools;
  for (const json* c : rows)
    if (const auto name = text(*c, {"vendor_tool", "name"});
        !name.empty() && std::find(tools.begin(), tools.end(), name) == tools.end())
      tools.push_back(name);
  if (!tools.empty()) {
    std::string list;
    for (const auto& t : tools) list += (list.empty() ? "" : ", ") + t;
    html << "<p>Vendor tools of this run: " << esc(list) << ".</p>\n";
  }
}

void write_skipped(std::ostream& html, const json& run) {
  std::vector<const json*> skipped;
  for (const json* c : cells_of(run))
    if (!is_ok(*c)) skipped.push_back(c);
  if (skipped.empty()) {
    html << "<p id=\"skipped\">None: every cell of the matrix ran.</p>\n";
    return;
  }
  html << "<table class=\"bench\" id=\"skipped\">\n<thead><tr><th>cell</th><th>status</th><th>reason</th></tr>"
          "</thead>\n<tbody>\n";
  for (const json* c : skipped) {
    const std::string status = text(*c, {"status"});
    std::string cls;  // the status as a class name: letters, digits and _ only
    for (char ch : status) cls += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    html << "<tr data-cell=\"" << esc(text(*c, {"id"})) << "\" class=\"" << cls << "\"><td class=\"key\">"
         << esc(text(*c, {"id"})) << "</td><td class=\"key status\">" << esc(status) << "</td><td class=\"text\">"
         << esc(text(*c, {"reason"})) << "</td></tr>\n";
  }
  html << "</tbody>\n</table>\n";
}

bool has_faults(const json& c) {
  return is_ok(c) && (number(c, {"loss_percent"}).value_or(0) > 0 || member(c, {"recovery"}) ||
                      member(c, {"events", "deadline"}) || member(c, {"events", "liveliness"}));
}

/// "A of B" of two members of `j` (e.g. lost of sent), "-" if either is missing.
std::string of_text(const json* j, const char* part, const char* whole) {
  const auto a = j ? number(*j, {part}) : std::nullopt, b = j ? number(*j, {whole}) : std::nullopt;
  return a && b ? shown(*a) + " of " + shown(*b) : "-";
}

/// "LIMIT s / DETECTED s" of a deadline or liveliness event, "-" if none.
std::string event_text(const json& c, const char* event, const char* limit_key) {
  const auto limit = number(c, {"events", event, limit_key});
  const auto after = number(c, {"events", event, "detected_after_s"});
  if (!limit && !after) return "-";
  return (limit ? shown(*limit) + " s" : "?") + " / " + (after ? shown(*after) + " s" : "not detected");
}

void write_faults(std::ostream& html, const json& run) {
  const auto rate = summary_rate(run);
  std::vector<const json*> rows;
  for (const json* c : cells_of(run))
    if (has_faults(*c)) rows.push_back(c);
  if (rows.empty()) {
    html << "<p id=\"faults\">None: no cell ran with link loss, an outage or a deadline or liveliness event.</p>\n";
    return;
  }
  html << "<p>Every cell that ran with packet loss on its link, an outage (recovery) or a deadline or liveliness "
          "event. Lost pings at "
       << esc(rate ? rate_text(*rate) : "?")
       << " and in the throughput phase; outage and recovery times, and the samples repaired of those lost, from "
          "the cell's recovery measure; deadline and liveliness: the QoS period or lease against the time the "
          "missed deadline or the lost liveliness took to be detected.</p>\n"
       << "<table class=\"bench\" id=\"faults\">\n<thead><tr><th>cell</th><th>link loss %</th><th>lost pings</th>"
          "<th>lost in throughput phase</th><th>outage s</th><th>recovery s</th><th>repaired / lost</th>"
          "<th>deadline period / detected after</th><th>liveliness lease / detected after</th>"
          "<th>clock offset us</th></tr></thead>\n"
          "<tbody>\n";
  for (const json* c : rows) {
    const auto cell = [&](const std::string& v) {
      html << (v == "-" ? "<td class=\"na\">-</td>" : "<td>" + esc(v) + "</td>");
    };
    const auto num = [&](const Path& p) {
      const auto v = number(*c, p);
      return v ? shown(*v) : "-";
    };
    html << "<tr data-cell=\"" << esc(text(*c, {"id"})) << "\"><td class=\"key\">" << esc(text(*c, {"id"})) << "</td>";
    cell(num({"loss_percent"}));
    cell(of_text(latency_at(*c, rate), "lost", "sent"));
    cell(of_text(member(*c, {"throughput"}), "lost", "sent"));
    cell(num({"recovery", "outage_s"}));
    cell(num({"recovery", "recovery_s"}));
    const auto repaired = number(*c, {"recovery", "repaired"}), lost = number(*c, {"recovery", "lost"});
    cell(repaired && lost ? shown(*repaired) + " / " + shown(*lost) : "-");
    cell(event_text(*c, "deadline", "period_s"));
    cell(event_text(*c, "liveliness", "lease_s"));
    const auto offset = number(*c, {"clock_offset_us"});
    const json* applied = member(*c, {"clock_offset_applied"});
    cell(offset ? shown(*offset) + (applied && applied->is_boolean() && applied->get<bool>() ? " (applied)" : "")
                : "-");
    html << "</tr>\n";
  }
  html << "</tbody>\n</table>\n";
  // What the link's loss rules did, per group (nftables counters).
  if (const json* counters = member(run, {"link_counters"}); counters && counters->is_object() && !counters->empty()) {
    html << "<p>The link's loss rules, per group (nftables counters in the two namespaces):</p>\n<ul id=\"link\">\n";
    for (const auto& [group, what] : counters->items())
      html << "<li>" << esc(group) << ": " << esc(what.is_string() ? what.get<std::string>() : what.dump())
           << "</li>\n";
    html << "</ul>\n";
  }
}

/// --baseline's comparison, when the run has one.
void write_baseline(std::ostream& html, const json& run) {
  const json* b = member(run, {"baseline"});
  if (!b || !b->is_object()) return;
  const json* regs = member(*b, {"regressions"});
  const std::size_t n = regs && regs->is_array() ? regs->size() : 0;
  html << "<h2 id=\"baseline-section\">Against the baseline</h2>\n<p>Compared with " << esc(text(*b, {"run"})) << ": "
       << esc(shown(number(*b, {"compared"}).value_or(0))) << " measures of the cells that ran in both; "
       << (n == 0 ? std::string("no regression.") : std::to_string(n) + " regressions (the command exits 1).")
       << " A measure regresses when it is worse by more than the largest of the relative threshold, the absolute "
          "floor (latencies) and the noise factor times the old cell's spread.</p>\n";
  if (n == 0) return;
  html << "<table class=\"bench\" id=\"regressions\">\n<thead><tr><th>cell</th><th>measure</th><th>old</th><th>new</th>"
          "<th>allowed change</th></tr></thead>\n<tbody>\n";
  for (const auto& r : *regs)
    html << "<tr data-cell=\"" << esc(text(r, {"cell"})) << "\"><td class=\"key\">" << esc(text(r, {"cell"}))
         << "</td><td>" << esc(text(r, {"measure"})) << "</td><td>" << esc(shown(number(r, {"old"}).value_or(0)))
         << "</td><td>" << esc(shown(number(r, {"new"}).value_or(0))) << "</td><td>"
         << esc(shown(number(r, {"allowed_change"}).value_or(0))) << "</td></tr>\n";
  html << "</tbody>\n</table>\n";
}

// ---- Figures: planned from the run alone, so the page can name them before gnuplot draws.

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

std::string file_part(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return out;
}

std::string gp_quote(const std::string& s) {  // a gnuplot single-quoted string: ' doubled
  std::string out = "'";
  for (char c : s) out += c == '\'' ? "''" : c == '\n' ? " " : std::string(1, c);
  return out + "'";
}

/// The look of the curves of group number `i` (the same in every figure): colour, and past
/// the palette a dash pattern and point type.
std::string look(std::size_t i) {
  static const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                   "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  const std::size_t n = std::size(kPalette);
  return std::string("lc rgb '") + kPalette[i % n] + "' dt " + std::to_string(1 + (i / n) % 4) + " pt " +
         std::to_string(5 + (i / n) % 4 * 2);
}

/// What the figures iterate over, in run order (sizes ascending).
struct Axes {
  std::vector<std::string> groups, topologies;
  std::vector<double> sizes;
  std::size_t group_index(const json& c) const {
    return static_cast<std::size_t>(std::find(groups.begin(), groups.end(), group_of(c)) - groups.begin());
  }
};

Axes axes_of(const json& run) {
  Axes a;
  const auto add = [](auto& list, const auto& v) {
    if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
  };
  for (const json* c : cells_of(run)) {
    add(a.groups, group_of(*c));  // of every cell: a group keeps its colour whatever ran
    if (!is_ok(*c)) continue;
    add(a.topologies, text(*c, {"topology"}));
    if (const auto s = number(*c, {"size"})) add(a.sizes, *s);
  }
  std::sort(a.sizes.begin(), a.sizes.end());
  return a;
}

std::vector<const json*> ok_cells(const json& run, const std::string& topology, std::optional<double> size = {}) {
  std::vector<const json*> out;
  for (const json* c : cells_of(run))
    if (is_ok(*c) && text(*c, {"topology"}) == topology && (!size || number(*c, {"size"}) == size)) out.push_back(c);
  return out;
}

/// A latency entry's one-way CDF as rows "us tail": tail = 1 - fraction (the fraction of the
/// samples above us; 0.01 at the p99, as the summary has it). The last point, the maximum,
/// would be at 0, which a log axis cannot show: it is drawn at 1/count, one sample.
std::string tail_rows(const json& entry) {
  const json* cdf = member(entry, {"one_way_us", "cdf"});
  if (!cdf || !cdf->is_array()) return "";
  const double count = number(entry, {"one_way_us", "count"}).value_or(0);
  std::string rows;
  for (const auto& p : *cdf) {
    if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number()) continue;
    const double us = p[0].get<double>(), fraction = p[1].get<double>();
    const double tail = fraction < 1 ? 1 - fraction : count > 0 ? 1 / count : 0;
    if (us > 0 && tail > 0) rows += shortest(us) + ' ' + shortest(tail) + '\n';
  }
  return rows;
}

/// One-way latency of each ok cell of a size and topology as its tail (1 - CDF), log-log: the
/// tail is spread out over decades instead of squashed against 1.
std::optional<Figure> cdf_figure(const json& run, const Axes& axes, double size, const std::string& topology) {
  const auto rate = summary_rate(run);
  Figure f{"cdf_" + shortest(size) + "_" + file_part(topology), "cdf", "", "", "", {}};
  for (const json* c : ok_cells(run, topology, size)) {
    const json* entry = latency_at(*c, rate);
    const std::string rows = entry ? tail_rows(*entry) : "";
    if (!rows.empty())
      f.curves.push_back({group_of(*c), rows, "using 1:2 with lines lw 2 " + look(axes.group_index(*c))});
  }
  if (f.curves.empty()) return std::nullopt;
  const std::string at = rate ? rate_text(*rate) : "?";
  f.title = "one-way latency tail, " + size_text(size) + ", " + topology + ", " + at;
  f.caption = "One curve per cell that ran (pair/transport/profile), pings at " + at +
              ". x: one-way latency (us, log); y: 1 - CDF, the fraction of the samples above x (log), so that the "
              "tail is spread out: a curve crosses 0.01 at its p99 and 0.001 at its p99.9. Its last point is its "
              "largest sample, drawn at 1/count (one sample). Further left and lower is better.";
  f.settings =
      "set logscale xy\nset grid\nset key outside right top\nset xlabel 'one-way latency (us)'\n"
      "set ylabel '1 - CDF (fraction of samples above x)'\nset yrange [*:1.5]\n";
  return f;
}

/// The x tics of sizes: "64 B", "4 KiB", ...
std::string size_tics(const std::vector<double>& sizes) {
  std::string tics;
  for (double s : sizes) tics += (tics.empty() ? "" : ", ") + gp_quote(size_text(s)) + " " + shortest(s);
  return "set xtics (" + tics + ")\n";
}

/// Throughput of each pair/transport/profile of a topology against the payload size.
std::optional<Figure> throughput_figure(const json& run, const Axes& axes, const std::string& topology) {
  Figure f{"throughput_" + file_part(topology), "throughput", "", "", "", {}};
  std::vector<double> sizes;
  for (const auto& group : axes.groups) {
    std::vector<std::pair<double, double>> points;  // (size, MB/s)
    for (const json* c : ok_cells(run, topology)) {
      const auto size = number(*c, {"size"}), mb = number(*c, {"throughput", "mb_per_s"});
      if (group_of(*c) == group && size && mb && *size > 0 && *mb > 0) points.emplace_back(*size, *mb);
    }
    if (points.empty()) continue;
    std::sort(points.begin(), points.end());
    std::string rows;
    for (const auto& [size, mb] : points) {
      rows += shortest(size) + ' ' + shortest(mb) + '\n';
      if (std::find(sizes.begin(), sizes.end(), size) == sizes.end()) sizes.push_back(size);
    }
    const std::size_t i = static_cast<std::size_t>(&group - axes.groups.data());
    f.curves.push_back({group, rows, "using 1:2 with linespoints lw 2 ps 1.2 " + look(i)});
  }
  if (f.curves.empty()) return std::nullopt;
  std::sort(sizes.begin(), sizes.end());
  f.title = "throughput against payload size, " + topology;
  f.caption =
      "One curve per pair/transport/profile: the samples that arrived in the throughput phase, in "
      "MB/s "
      "(log), against the payload size (log 2). Higher is better.";
  f.settings =
      "set logscale x 2\nset logscale y\nset grid\nset key outside right top\n"
      "set xlabel 'payload size'\nset ylabel 'throughput (MB/s)'\n" +
      size_tics(sizes) + "set xrange [" + shortest(sizes.front() / 1.5) + ":" + shortest(sizes.back() * 1.5) + "]\n";
  return f;
}

/// The paced rates (> 0) of the cells' latency entries, ascending.
std::vector<double> paced_rates(const std::vector<const json*>& cells) {
  std::vector<double> rates;
  for (const json* c : cells) {
    const json* entries = member(*c, {"latency"});
    if (!entries || !entries->is_array()) continue;
    for (const auto& e : *entries)
      if (const double hz = number(e, {"rate_hz"}).value_or(0);
          hz > 0 && std::find(rates.begin(), rates.end(), hz) == rates.end())
        rates.push_back(hz);
  }
  std::sort(rates.begin(), rates.end());
  return rates;
}

/// A cell's block of the rate figure: rows "rate p50 p99", the paced ones, a blank line (the
/// unpaced point is not joined to them), and the unpaced one at x = `unpaced_x`.
std::string rate_rows(const json& cell, double unpaced_x) {
  const json* entries = member(cell, {"latency"});
  if (!entries || !entries->is_array()) return "";
  std::vector<std::array<double, 3>> paced;  // (rate, p50, p99)
  std::string unpaced;
  for (const auto& e : *entries) {
    const auto hz = number(e, {"rate_hz"}), p50 = number(e, {"one_way_us", "p50"}),
               p99 = number(e, {"one_way_us", "p99"});
    if (!hz || !p50 || !p99 || !(*p50 > 0) || !(*p99 > 0)) continue;  // a log axis has no 0
    if (*hz > 0) paced.push_back({*hz, *p50, *p99});
    if (*hz == 0) unpaced = shortest(unpaced_x) + ' ' + shortest(*p50) + ' ' + shortest(*p99) + '\n';
  }
  if (paced.empty() && unpaced.empty()) return "";
  std::sort(paced.begin(), paced.end());
  std::string rows;
  for (const auto& [hz, p50, p99] : paced) rows += shortest(hz) + ' ' + shortest(p50) + ' ' + shortest(p99) + '\n';
  return rows + "\n" + unpaced;
}

/// One-way p50 and p99 against the rate at the smallest size of a topology; the unpaced run
/// (rate 0, which a log axis cannot show) is drawn at 4 x the fastest paced rate, past a
/// dotted line, its tic labelled "unpaced".
std::optional<Figure> rate_figure(const json& run, const Axes& axes, const std::string& topology) {
  std::optional<double> size;
  for (double s : axes.sizes)
    if (!size && !ok_cells(run, topology, s).empty()) size = s;
  if (!size) return std::nullopt;
  const auto cells = ok_cells(run, topology, size);
  const auto rates = paced_rates(cells);
  const double slowest = rates.empty() ? 1 : rates.front(), fastest = rates.empty() ? 1 : rates.back();
  const double unpaced_x = fastest * 4;
  Figure f{"latency_rate_" + file_part(topology), "rate", "", "", "", {}};
  bool any_unpaced = false;
  for (const json* c : cells) {
    const std::string rows = rate_rows(*c, unpaced_x);
    if (rows.empty()) continue;
    any_unpaced = any_unpaced || !rows.ends_with("\n\n");  // a blank line last: no unpaced point
    const std::string l = look(axes.group_index(*c)), colour = l.substr(0, l.find(" dt"));
    f.curves.push_back({group_of(*c), rows, "using 1:2 with linespoints lw 2 pt 7 " + colour});
    f.curves.push_back({"", "", "using 1:3 with linespoints lw 1 dt 2 pt 6 " + colour});  // the same block
  }
  if (f.curves.empty()) return std::nullopt;
  std::string tics;
  for (double hz : rates) tics += gp_quote(shown(hz)) + " " + shortest(hz) + ", ";
  tics += "'unpaced' " + shortest(unpaced_x);
  const double split = std::sqrt(fastest * unpaced_x);
  f.title = "one-way latency against rate, " + size_text(*size) + ", " + topology;
  f.caption =
      "One-way latency p50 (solid, filled points) and p99 (dashed, open points, same colour) of each "
      "pair/transport/profile at " +
      size_text(*size) +
      " (the smallest size that ran), against the rate the pings are sent at (log x; latency log). " +
      (any_unpaced ? "The unpaced run (next ping as soon as the last pong is back) is the point right of "
                     "the dotted line, labelled unpaced."
                   : "No unpaced run.");
  f.settings =
      "set logscale xy\nset grid\nset key outside right top\nset xlabel 'rate (Hz)'\n"
      "set ylabel 'one-way latency (us)'\nset xtics (" +
      tics + ")\nset xrange [" + shortest(slowest / 2) + ":" + shortest(unpaced_x * 2) + "]\n" + "set arrow from " +
      shortest(split) + ", graph 0 to " + shortest(split) + ", graph 1 nohead dt 3 lc rgb '#888888'\n";
  return f;
}

std::vector<Figure> plan_figures(const json& run) {
  const Axes axes = axes_of(run);
  std::vector<Figure> figures;
  const auto add = [&](std::optional<Figure> f) {
    if (f) figures.push_back(std::move(*f));
  };
  for (const auto& topology : axes.topologies)
    for (double size : axes.sizes) add(cdf_figure(run, axes, size, topology));
  for (const auto& topology : axes.topologies) add(throughput_figure(run, axes, topology));
  for (const auto& topology : axes.topologies) add(rate_figure(run, axes, topology));
  return figures;
}

void write_figures(std::ostream& html, const std::vector<Figure>& figures, const std::string& section,
                   const std::string& none) {
  bool any = false;
  for (const auto& f : figures) {
    if (f.section != section) continue;
    any = true;
    html << "<figure id=\"fig-" << esc(f.name) << "\">\n<img src=\"plots/" << esc(f.name) << ".png\" alt=\""
         << esc(f.title) << "\">\n<figcaption><b>" << esc(f.title) << "</b>" << esc(f.caption)
         << "</figcaption>\n</figure>\n";
  }
  if (!any) html << "<p>" << esc(none) << "</p>\n";
}

std::string report_html(const json& run, const std::vector<Figure>& figures) {
  std::ostringstream html;
  const std::string started = text(run, {"started_utc"});
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<title>plexus bench: " << esc(started) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
       << "<h1>plexus bench: " << esc(started) << "</h1>\n";
  write_facts(html, run);
  html << "<nav><ul>\n<li><a href=\"#summary-section\">Summary</a></li>\n"
          "<li><a href=\"#skipped-section\">Cells that did not run</a></li>\n"
          "<li><a href=\"#cdf-section\">Latency distributions</a></li>\n"
          "<li><a href=\"#throughput-section\">Throughput against payload size</a></li>\n"
          "<li><a href=\"#rate-section\">Latency against rate</a></li>\n"
          "<li><a href=\"#faults-section\">Loss and recovery</a></li>\n</ul></nav>\n";
  write_baseline(html, run);
  html << "<h2 id=\"summary-section\">Summary</h2>\n";
  write_summary(html, run);
  html << "<h2 id=\"skipped-section\">Cells that did not run</h2>\n";
  write_skipped(html, run);
  html << "<h2 id=\"cdf-section\">Latency distributions</h2>\n";
  write_figures(html, figures, "cdf", "None: no cell that ran has a latency distribution.");
  html << "<h2 id=\"throughput-section\">Throughput against payload size</h2>\n";
  write_figures(html, figures, "throughput", "None: no cell that ran has a throughput.");
  html << "<h2 id=\"rate-section\">Latency against rate</h2>\n";
  write_figures(html, figures, "rate", "None: no cell that ran has latencies.");
  html << "<h2 id=\"faults-section\">Loss and recovery</h2>\n";
  write_faults(html, run);
  html << "<p>Data: <a href=\"run.json\">run.json</a> (everything measured), <a href=\"cells.csv\">cells.csv</a> "
          "(one row per cell and rate). Written by <code>plexus bench</code>; <code>plots/bench.gp</code> redraws "
          "every figure (<code>gnuplot plots/bench.gp</code> from this folder).</p>\n</body>\n</html>\n";
  return html.str();
}

// ---- CSV.

struct Column {
  const char* name;
  bool per_rate;  ///< read from the latency entry of the row, not from the cell
  Path path;
};

const std::vector<Column>& csv_columns() {
  static const std::vector<Column> columns = {
      {"id", false, {"id"}},
      {"pair", false, {"pair"}},
      {"writer_dds", false, {"writer_dds"}},
      {"reader_dds", false, {"reader_dds"}},
      {"transport", false, {"transport"}},
      {"profile", false, {"profile"}},
      {"reliability", false, {"reliability"}},
      {"size", false, {"size"}},
      {"topology", false, {"topology"}},
      {"loss_percent", false, {"loss_percent"}},
      {"status", false, {"status"}},
      {"reason", false, {"reason"}},
      {"rate_hz", true, {"rate_hz"}},
      {"one_way_count", true, {"one_way_us", "count"}},
      {"one_way_p50_us", true, {"one_way_us", "p50"}},
      {"one_way_p90_us", true, {"one_way_us", "p90"}},
      {"one_way_p99_us", true, {"one_way_us", "p99"}},
      {"one_way_p999_us", true, {"one_way_us", "p999"}},
      {"one_way_max_us", true, {"one_way_us", "max"}},
      {"round_trip_count", true, {"round_trip_us", "count"}},
      {"round_trip_p50_us", true, {"round_trip_us", "p50"}},
      {"round_trip_p90_us", true, {"round_trip_us", "p90"}},
      {"round_trip_p99_us", true, {"round_trip_us", "p99"}},
      {"round_trip_p999_us", true, {"round_trip_us", "p999"}},
      {"round_trip_max_us", true, {"round_trip_us", "max"}},
      {"sent", true, {"sent"}},
      {"received", true, {"received"}},
      {"lost", true, {"lost"}},
      {"late", true, {"late"}},
      {"throughput_samples_per_s", false, {"throughput", "samples_per_s"}},
      {"throughput_mb_per_s", false, {"throughput", "mb_per_s"}},
      {"throughput_sent", false, {"throughput", "sent"}},
      {"throughput_received", false, {"throughput", "received"}},
      {"throughput_lost", false, {"throughput", "lost"}},
      {"throughput_seconds", false, {"throughput", "seconds"}},
      {"cpu_writer_percent", false, {"cpu_percent", "writer"}},
      {"cpu_reader_percent", false, {"cpu_percent", "reader"}},
      {"clock_offset_us", false, {"clock_offset_us"}},
      {"recovery_outage_s", false, {"recovery", "outage_s"}},
      {"recovery_s", false, {"recovery", "recovery_s"}},
      {"recovery_repaired", false, {"recovery", "repaired"}},
      {"recovery_lost", false, {"recovery", "lost"}},
      {"deadline_period_s", false, {"events", "deadline", "period_s"}},
      {"deadline_detected_after_s", false, {"events", "deadline", "detected_after_s"}},
      {"liveliness_lease_s", false, {"events", "liveliness", "lease_s"}},
      {"liveliness_detected_after_s", false, {"events", "liveliness", "detected_after_s"}},
      {"spread_one_way_p50_us", false, {"spread", "one_way_p50_us"}},
      {"spread_round_trip_p50_us", false, {"spread", "round_trip_p50_us"}},
      {"spread_throughput_samples_per_s", false, {"spread", "throughput_samples_per_s"}},
      {"vendor_tool", false, {"vendor_tool", "name"}},
      {"vendor_round_trip_p50_us", false, {"vendor_tool", "round_trip_us", "p50"}},
      {"vendor_round_trip_p99_us", false, {"vendor_tool", "round_trip_us", "p99"}},
      {"vendor_samples_per_s", false, {"vendor_tool", "throughput", "samples_per_s"}},
      {"vendor_mb_per_s", false, {"vendor_tool", "throughput", "mb_per_s"}},
      {"ratio_round_trip_p50", false, {"ratio", "round_trip_p50"}},
      {"ratio_round_trip_p99", false, {"ratio", "round_trip_p99"}},
      {"ratio_throughput", false, {"ratio", "throughput"}},
  };
  return columns;
}

std::string csv_field(const std::string& s) {  // RFC 4180: quoted if it has , " or a line break
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void csv_row(std::string& out, const json& cell, const json* entry) {
  bool first = true;
  for (const auto& col : csv_columns()) {
    if (!first) out += ',';
    first = false;
    if (col.per_rate && !entry) continue;
    out += csv_field(text(col.per_rate ? *entry : cell, col.path));
  }
  out += '\n';
}

void write_file(const std::filesystem::path& path, const std::string& content) {
  std::ofstream f(path, std::ios::binary);
  f << content;
  f.close();
  if (!f) throw std::runtime_error("cannot write " + path.string());
}

/// The figures' data files and plots/bench.gp, then one gnuplot run for all of them (one
/// start instead of one per figure). The script reads and writes paths relative to the report
/// folder, so that it can be rerun from there.
void draw(const std::vector<Figure>& figures, const std::filesystem::path& dir) {
  const std::string gnuplot = find_program("gnuplot");
  if (gnuplot.empty()) throw std::runtime_error("gnuplot not found (install gnuplot-nox)");
  std::string script = "# The figures of report.html (plexus bench): gnuplot plots/bench.gp, from the report folder.\n";
  for (const auto& f : figures) {
    std::string data, plot;
    int block = -1;  // blocks of the data file, two blank lines apart: gnuplot's "index"
    for (const auto& c : f.curves) {
      if (!c.data.empty() || block < 0) {
        data += "# " + (c.title.empty() ? "(no title)" : c.title) + "\n" + c.data + "\n\n";
        ++block;
      }
      plot += std::string(plot.empty() ? "" : ", \\\n     ") + gp_quote("plots/" + f.name + ".dat") + " index " +
              std::to_string(block) + " " + c.style + (c.title.empty() ? " notitle" : " title " + gp_quote(c.title));
    }
    write_file(dir / "plots" / (f.name + ".dat"), data);
    script += "\nreset\nset terminal pngcairo size 1100,560 noenhanced font 'sans,10'\nset output " +
              gp_quote("plots/" + f.name + ".png") + "\nset title " + gp_quote(f.title) + "\n" + f.settings + "plot " +
              plot + "\n";
  }
  script += "unset output\n";
  const auto gp = dir / "plots" / "bench.gp";
  write_file(gp, script);
  std::string out;
  const auto abs = std::filesystem::absolute(dir);
  if (run_program(gnuplot, {"-e", "cd " + gp_quote(abs.string()), (abs / "plots" / "bench.gp").string()}, out, {},
                  true) != 0)
    throw std::runtime_error("gnuplot failed on " + gp.string() + ": " + out);
  for (const auto& f : figures) {
    const auto png = dir / "plots" / (f.name + ".png");
    std::error_code ec;
    if (std::filesystem::file_size(png, ec) == 0 || ec)
      throw std::runtime_error("gnuplot did not draw " + png.string() + ": " + out);
  }
}

std::string csv_of(const json& run) {
  std::string out;
  for (const auto& col : csv_columns()) out += (out.empty() ? "" : ",") + std::string(col.name);
  out += '\n';
  for (const json* cell : cells_of(run)) {
    std::size_t rows = 0;
    if (const json* entries = member(*cell, {"latency"}); entries && entries->is_array())
      for (const auto& e : *entries)
        if (e.is_object()) csv_row(out, *cell, &e), ++rows;
    if (rows == 0) csv_row(out, *cell, nullptr);
  }
  return out;
}

void write_report(const json& run, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir / "plots", ec);
  if (!std::filesystem::is_directory(dir / "plots"))
    throw std::runtime_error("cannot create " + (dir / "plots").string());
  write_file(dir / "cells.csv", csv_of(run));
  if (!std::filesystem::exists(dir / "run.json")) write_file(dir / "run.json", run.dump(1) + "\n");
  const auto figures = plan_figures(run);
  if (!figures.empty()) draw(figures, dir);
  write_file(dir / "report.html", report_html(run, figures));
}

}  // namespace
}  // namespace plexus::cli::bench_report_impl

namespace plexus::cli {

std::string bench_csv(const nlohmann::ordered_json& run) { return bench_report_impl::csv_of(run); }

std::string bench_report_html(const nlohmann::ordered_json& run) {
  return bench_report_impl::report_html(run, bench_report_impl::plan_figures(run));
}

void write_bench_report(const nlohmann::ordered_json& run, const std::string& out_dir) {
  bench_report_impl::write_report(run, out_dir);
}

}  // namespace plexus::cli
