#include "plexus/scenario/report.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/scenario/evaluation.hpp"
#include "plexus/scenario/expectation.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

/// A CSV file of the run folder: its stem and its column names.
struct Table {
  std::string stem;  ///< file name without .csv
  std::string path;  ///< relative to the run folder
  std::vector<std::string> columns;

  int column(const std::string& name) const {  // 1-based gnuplot column, or 0
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return static_cast<int>(i) + 1;
    return 0;
  }
};

std::vector<Table> read_tables(const fs::path& run_dir, const std::string& sub) {
  std::vector<Table> out;
  if (!fs::is_directory(run_dir / sub)) return out;
  for (const auto& e : fs::directory_iterator(run_dir / sub)) {
    if (e.path().extension() != ".csv") continue;
    std::ifstream in(e.path());
    std::string header;
    if (!std::getline(in, header)) throw InputError(e.path().string() + ": empty CSV file");
    Table t{e.path().stem().string(), sub + "/" + e.path().filename().string(), {}};
    std::stringstream ss(header);
    for (std::string col; std::getline(ss, col, ',');) t.columns.push_back(col);
    if (t.columns.size() < 2 || t.columns[0] != "t") throw InputError(e.path().string() + ": not a plexus CSV (header)");
    out.push_back(std::move(t));
  }
  std::sort(out.begin(), out.end(), [](const Table& a, const Table& b) { return a.stem < b.stem; });
  return out;
}

std::string robot_of(const std::string& stem) {
  const auto dot = stem.find('.');
  return dot == std::string::npos ? std::string() : stem.substr(0, dot);
}

std::string quote(const std::string& s) { return "'" + s + "'"; }

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void plot_begin(std::ostream& gp, const std::string& png, const std::string& title, const std::string& xlabel,
                const std::string& ylabel) {
  gp << "set output " << quote(png) << "\nset title " << quote(title) << "\nset xlabel " << quote(xlabel)
     << "\nset ylabel " << quote(ylabel) << "\n";
}

}  // namespace

Report write_report(const fs::path& run_dir) {
  const std::string dir = run_dir.string();
  if (!fs::is_directory(run_dir)) throw InputError(dir + ": no such run folder");
  for (const char* f : {"metrics.json", "scenario.resolved.yaml"})
    if (!fs::is_regular_file(run_dir / f)) throw InputError(dir + ": not a run folder (no " + f + ")");
  nlohmann::ordered_json metrics;
  {
    std::ifstream in(run_dir / "metrics.json");
    metrics = nlohmann::ordered_json::parse(in, nullptr, false);
    if (metrics.is_discarded() || !metrics.is_object()) throw InputError(dir + "/metrics.json: not a JSON object");
  }
  const YAML::Node scenario = load_yaml_file((run_dir / "scenario.resolved.yaml").string());
  const std::vector<Table> signals = read_tables(run_dir, "signals");
  if (signals.empty()) throw InputError(dir + ": not a run folder (no signals/*.csv)");
  const std::vector<Table> series = read_tables(run_dir, "series");

  std::set<std::string> sensors;  // "<robot>.<sensor>" stems: plotted as points
  if (scenario["robots"] && scenario["robots"].IsMap())
    for (const auto& r : scenario["robots"])
      if (r.second["sensors"] && r.second["sensors"].IsMap())
        for (const auto& s : r.second["sensors"]) sensors.insert(r.first.Scalar() + "." + s.first.Scalar());

  fs::create_directories(run_dir / "plots");
  Report report;
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1000,600 noenhanced\nset datafile separator ','\nset grid\nset key outside right\n";
  std::map<std::string, const Table*> states;
  for (const auto& t : signals)
    if (t.stem == robot_of(t.stem) + ".truth.state") states[robot_of(t.stem)] = &t;

  for (const auto& t : signals) {
    const std::string png = "plots/" + t.stem + ".png";
    plot_begin(gp, png, t.stem, "t [s]", "value");
    const Table* truth = nullptr;
    if (auto it = states.find(robot_of(t.stem)); it != states.end() && it->second != &t) truth = it->second;
    std::string sep = "plot ";
    for (std::size_t c = 2; c < t.columns.size(); ++c) {
      gp << sep << quote(t.path) << " every ::1 using 1:" << c + 1 << " with lines title " << quote(t.columns[c]);
      sep = ", \\\n  ";
      if (truth && truth->column(t.columns[c]))
        gp << sep << quote(truth->path) << " every ::1 using 1:" << truth->column(t.columns[c])
           << " with lines dt 2 title " << quote(t.columns[c] + " (truth)");
    }
    gp << "\n";
    report.plots.push_back(run_dir / png);
  }
  for (const auto& [robot, state] : states) {
    if (!state->column("x") || !state->column("y")) continue;
    const std::string png = "plots/" + robot + ".trajectory.png";
    plot_begin(gp, png, robot + " trajectory", "x [m]", "y [m]");
    gp << "set size ratio -1\nplot ";
    std::string sep;
    for (const auto& t : signals) {
      if (robot_of(t.stem) != robot || !t.column("x") || !t.column("y")) continue;
      const bool points = sensors.count(t.stem) > 0;
      gp << sep << quote(t.path) << " every ::1 using " << t.column("x") << ":" << t.column("y")
         << (points ? " with points pt 7 ps 0.3" : " with lines") << " title " << quote(t.stem);
      sep = ", \\\n  ";
    }
    gp << "\nset size noratio\n";
    report.plots.push_back(run_dir / png);
  }
  for (const auto& t : series) {
    const std::string png = "plots/series." + t.stem + ".png";
    plot_begin(gp, png, t.stem, "t [s]", t.stem);
    gp << "plot " << quote(t.path) << " every ::1 using 1:2 with lines title " << quote(t.stem) << "\n";
    report.plots.push_back(run_dir / png);
  }
  {
    std::ofstream out(run_dir / "plots" / "report.gp");
    out << gp.str();
    if (!out) throw InputError(dir + "/plots/report.gp: cannot write file");
  }
  const std::string cmd = "cd " + shell_quote(dir) + " && gnuplot plots/report.gp 2> plots/gnuplot.log";
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("gnuplot failed (is gnuplot-nox installed?); see " + dir + "/plots/gnuplot.log");
  for (const auto& p : report.plots)
    if (!fs::is_regular_file(p)) throw std::runtime_error("gnuplot did not write " + p.string());

  // The metrics table against the expectations of the resolved scenario.
  std::map<std::string, std::vector<Expectation>> bounds;
  if (scenario["expectations"] && scenario["expectations"].IsMap())
    for (const auto& kv : scenario["expectations"]) {
      Expectation e;
      if (kv.second.IsScalar() && parse_expectation(kv.first.Scalar(), kv.second.Scalar(), e))
        bounds[e.metric].push_back(e);
    }
  std::ostringstream md;
  const std::string name = scenario["name"] && scenario["name"].IsScalar() ? scenario["name"].Scalar() : dir;
  md << "# Report: " << name << "\n\n";
  md << "Digest `" << (metrics.contains("digest") ? metrics["digest"].get<std::string>() : "?") << "`\n\n";
  std::ostringstream table;
  table << "| metric | value | expectation | result |\n|---|---|---|---|\n";
  for (const auto& [metric, value] : metrics.items()) {
    if (metric == "digest") continue;
    const double v = value.is_number() ? value.get<double>() : std::nan("");
    std::string bound = "-", result = "-";
    for (const auto& e : bounds[metric]) {
      bound = (bound == "-" ? "" : bound + ", ") + e.op_text() + " " + format_number(e.bound);
      result = (result == "-" || result == "pass") && e.holds(v) ? "pass" : "FAIL";
    }
    table << "| " << metric << " | " << format_number(v) << " | " << bound << " | " << result << " |\n";
    if (result == "FAIL") ++report.failed;
  }
  // An expectation whose metric metrics.json lacks is a row too: missing, and FAIL.
  for (const auto& [metric, es] : bounds) {
    if (metrics.contains(metric)) continue;
    std::string bound;
    for (const auto& e : es) bound += (bound.empty() ? "" : ", ") + std::string(e.op_text()) + " " + format_number(e.bound);
    table << "| " << metric << " | missing | " << bound << " | FAIL |\n";
    ++report.failed;
  }
  report.table = table.str();
  md << report.table;
  md << "\n## Plots\n";
  for (const auto& p : report.plots) md << "\n![" << p.stem().string() << "](plots/" << p.filename().string() << ")\n";
  report.markdown = run_dir / "report.md";
  std::ofstream out(report.markdown);
  out << md.str();
  if (!out) throw InputError(report.markdown.string() + ": cannot write file");
  return report;
}

}  // namespace plexus::scenario
