#include "plexus/evaluation/report_html.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "plexus/base/html_escape.hpp"
#include "plexus/base/report_page_style.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/expectation.hpp"

namespace plexus::scenario {
namespace {

std::string esc(const std::string& s) { return html_escape(s); }

std::string anchor(const std::string& file) {
  std::string id = "fig-";
  for (char c : file.substr(file.rfind('/') + 1))
    id += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '-';
  return id;
}

/// Our value as the table shows it: 4 significant digits (the full value in its tooltip
/// and in metrics.json), or the text ("missing", "nan").
std::string value_cell(const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(v)) return esc(value);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return "<span title=\"" + esc(value) + "\">" + buf + "</span>";
}

// The report's own tables; the page, headings and figures: kReportPageStyle.
constexpr const char* kStyle = R"(
.facts { color: #444; }
.facts span { margin-right: 1.5em; white-space: nowrap; }
table.comparison { border-collapse: collapse; margin: 1em 0; }
table.comparison th, table.comparison td { border: 1px solid #bbb; padding: .3em .7em; text-align: left; }
table.comparison th { background: #eee; }
table.comparison td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.pass td.result { background: #d8f0d8; color: #145214; font-weight: bold; }
tr.fail td.result { background: #f6d4d4; color: #8a1010; font-weight: bold; }
tr.inconsistent td.result { background: #efe6c8; color: #5a4a10; font-weight: bold; }
tr.missing td.value { color: #8a1010; font-style: italic; }
.summary { font-weight: bold; }
.summary.fail { color: #8a1010; }
.summary.pass { color: #145214; }
)";

void write_figures(std::ostream& html, const std::vector<Figure>& figures, const std::string& section,
                   const std::string& robot) {
  for (const auto& f : figures) {
    if (f.section != section || f.robot != robot) continue;
    html << "<figure id=\"" << anchor(f.file) << "\">\n<img src=\"" << esc(f.file) << "\" alt=\"" << esc(f.title)
         << "\">\n<figcaption><b>" << esc(f.title) << "</b>" << esc(f.caption) << "</figcaption>\n</figure>\n";
  }
}

}  // namespace

std::string report_html(const ReportInputs& in, const Comparison& comparison, const std::vector<Figure>& figures) {
  const std::string scenario_name = scalar_or_empty(in.scenario, "name");
  const std::string name = scenario_name.empty() ? in.dir.filename().string() : scenario_name;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<title>plexus report: " << esc(name) << "</title>\n<style>" << kReportPageStyle << kStyle
       << "</style>\n</head>\n<body>\n";
  html << "<h1>Report: " << esc(name) << "</h1>\n";
  if (const std::string d = scalar_or_empty(in.scenario, "description"); !d.empty())
    html << "<p>" << esc(d) << "</p>\n";
  html << "<p class=\"facts\"><span>duration " << esc(scalar_or_empty(in.scenario, "duration"))
       << " s</span><span>base step " << esc(scalar_or_empty(in.scenario, "step")) << " s</span><span>seed "
       << esc(scalar_or_empty(in.scenario, "seed")) << "</span><span>digest <code>"
       << esc(in.metrics.contains("digest") && in.metrics["digest"].is_string()
                  ? in.metrics["digest"].get<std::string>()
                  : "?")
       << "</code></span></p>\n";

  int with_bound = 0;
  for (const auto& r : comparison.rows)
    if (r.result != "-") ++with_bound;
  html << "<nav><ul>\n<li><a href=\"#comparison\">Comparison with the papers</a></li>\n"
       << "<li><a href=\"#papers\">The papers' figures</a></li>\n";
  for (const auto& robot : in.robots())
    html << "<li><a href=\"#robot-" << esc(robot) << "\">Robot " << esc(robot) << "</a></li>\n";
  html << "<li><a href=\"#series\">Metric series</a></li>\n</ul></nav>\n";

  html << "<h2 id=\"comparison\">Comparison with the papers</h2>\n";
  html << "<p class=\"summary " << (comparison.failed ? "fail" : "pass") << "\">"
       << with_bound - comparison.failed - comparison.inconsistent << " of " << with_bound << " expectations met"
       << (comparison.failed ? " (FAIL rows below)" : "");
  if (comparison.inconsistent)
    html << "; " << comparison.inconsistent
         << " not met are inconsistent in the paper (its own text cannot produce them; the evidence is named in the "
            "row) and do not fail the run";
  html << ".</p>\n";
  html << "<table class=\"comparison\">\n<thead><tr><th>metric</th><th>paper</th><th>ours</th><th>bound</th>"
          "<th>result</th></tr></thead>\n<tbody>\n";
  for (const auto& r : comparison.rows) {
    const std::string cls = r.value == "missing"              ? "fail missing"
                            : r.result == "FAIL"              ? "fail"
                            : r.result == "pass"              ? "pass"
                            : r.result == kInconsistentResult ? "inconsistent"
                                                              : "none";
    html << "<tr class=\"" << cls << "\"><td class=\"metric\"><code>" << esc(r.metric)
         << "</code></td><td class=\"paper\">" << esc(r.paper.empty() ? "-" : r.paper)
         << "</td><td class=\"value num\">" << value_cell(r.value) << "</td><td class=\"bound\">" << esc(r.bound)
         << "</td><td class=\"result\">" << esc(r.result)
         << (r.evidence.empty() ? "" : "<br><small>evidence: " + esc(r.evidence) + "</small>") << "</td></tr>\n";
  }
  html << "</tbody>\n</table>\n";
  html << "<p>paper: the published figure the metric reproduces (the metric's <code>paper</code> key in the scenario); "
          "ours: this run's value (metrics.json); bound: the scenario's expectation; a metric that metrics.json lacks "
          "is <i>missing</i> and fails.</p>\n";

  html << "<h2 id=\"papers\">The papers' figures</h2>\n";
  bool any_paper = false;
  for (const auto& f : figures) any_paper = any_paper || f.section == "paper";
  if (!any_paper)
    html << "<p>None: no robot of this run has the signals that one of the papers' figures needs "
            "(docs/scenarios.md, \"plexus report\").</p>\n";
  for (const auto& robot : in.robots()) write_figures(html, figures, "paper", robot);

  for (const auto& robot : in.robots()) {
    html << "<h2 id=\"robot-" << esc(robot) << "\">Robot " << esc(robot) << ": its signals</h2>\n";
    write_figures(html, figures, "signals", robot);
  }
  bool other = false;
  for (const auto& f : figures) other = other || (f.section == "signals" && f.robot.empty());
  if (other) {
    html << "<h2 id=\"other\">Signals of no robot</h2>\n";
    write_figures(html, figures, "signals", "");
  }
  html << "<h2 id=\"series\">Metric series</h2>\n";
  write_figures(html, figures, "series", "");
  html << "<p class=\"facts\">Written by <code>plexus report</code>; <code>plots/report.gp</code> redraws every "
          "figure (<code>gnuplot plots/report.gp</code> from the run folder).</p>\n</body>\n</html>\n";
  return html.str();
}

}  // namespace plexus::scenario
