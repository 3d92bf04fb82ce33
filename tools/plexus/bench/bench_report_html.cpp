#include "bench/bench_report_html.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

#include "plexus/base/html_escape.hpp"
#include "plexus/base/report_page_style.hpp"

namespace plexus::cli::bench_report_impl {
namespace {

std::string esc(const std::string& s) { return html_escape(s); }

// The report's own tables; the page, headings and figures: kReportPageStyle.
constexpr const char* kStyle = R"(
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

}  // namespace

std::string report_html(const json& run, const std::vector<Figure>& figures) {
  std::ostringstream html;
  const std::string started = text(run, {"started_utc"});
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<title>plexus bench: " << esc(started) << "</title>\n<style>" << kReportPageStyle << kStyle
       << "</style>\n</head>\n<body>\n"
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

}  // namespace plexus::cli::bench_report_impl
