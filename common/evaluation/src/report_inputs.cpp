#include "plexus/evaluation/report_inputs.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "plexus/base/input_error.hpp"
#include "plexus/base/yaml_reader.hpp"
#include "plexus/evaluation/run_folder.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

std::vector<ReportTable> read_tables(const fs::path& dir, const std::string& sub) {
  std::vector<ReportTable> out;
  if (!fs::is_directory(dir / sub)) return out;
  for (const auto& e : fs::directory_iterator(dir / sub)) {
    if (e.path().extension() != ".csv") continue;
    std::ifstream in(e.path());
    std::string header;
    if (!std::getline(in, header)) throw InputError(e.path().string() + ": empty CSV file");
    ReportTable t;
    t.stem = e.path().stem().string();
    t.path = sub + "/" + e.path().filename().string();
    std::stringstream ss(header);
    for (std::string col; std::getline(ss, col, ',');) t.columns.push_back(col);
    if (t.columns.size() < 2 || t.columns[0] != "t")
      throw InputError(e.path().string() + ": not a plexus CSV (header)");
    t.units.assign(t.columns.size(), std::nullopt);
    t.units[0] = "s";
    out.push_back(std::move(t));
  }
  std::sort(out.begin(), out.end(), [](const ReportTable& a, const ReportTable& b) { return a.stem < b.stem; });
  return out;
}

std::string robot_of(const std::string& name, const std::vector<std::string>& robots) {
  const auto slash = name.find('/');
  if (slash == std::string::npos) return "";
  const std::string r = name.substr(0, slash);
  return std::find(robots.begin(), robots.end(), r) != robots.end() ? r : "";
}

/// signals.json: names, producers and units of the signal tables.
void read_signal_index(const fs::path& dir, std::vector<ReportTable>& signals) {
  const fs::path file = dir / "signals.json";
  if (!fs::is_regular_file(file)) {  // an older run folder: names from the file names
    for (auto& t : signals) {
      t.name = t.stem;
      std::replace(t.name.begin(), t.name.end(), '.', '/');
    }
    return;
  }
  std::ifstream in(file);
  const auto index = nlohmann::json::parse(in, nullptr, false);
  if (index.is_discarded() || !index.is_object()) throw InputError(file.string() + ": not a JSON object");
  for (const auto& [name, entry] : index.items()) {
    if (!entry.is_object() || !entry.contains("file") || !entry["file"].is_string())
      throw InputError(file.string() + ": " + name + ": expected {\"file\", \"producer\", \"message\", \"units\"}");
    const std::string path = entry["file"].get<std::string>();
    auto t = std::find_if(signals.begin(), signals.end(), [&](const ReportTable& s) { return s.path == path; });
    if (t == signals.end()) continue;  // listed, but its CSV was removed: nothing to plot
    t->name = name;
    if (entry.contains("producer") && entry["producer"].is_string()) t->producer = entry["producer"].get<std::string>();
    if (entry.contains("units") && entry["units"].is_object())
      for (const auto& [field, unit] : entry["units"].items()) {
        const int c = t->column(field);
        if (c > 0 && unit.is_string()) t->units[static_cast<std::size_t>(c - 1)] = unit.get<std::string>();
      }
  }
  for (auto& t : signals)
    if (t.name.empty()) {
      t.name = t.stem;
      std::replace(t.name.begin(), t.name.end(), '.', '/');
    }
}

}  // namespace

int ReportTable::column(const std::string& field) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == field) return static_cast<int>(i) + 1;
  return 0;
}

std::optional<std::string> ReportTable::unit(const std::string& field) const {
  const int c = column(field);
  return c > 0 ? units[static_cast<std::size_t>(c - 1)] : std::nullopt;
}

std::vector<std::string> ReportTable::fields() const {
  const std::size_t first = columns.size() > 1 && columns[1] == "step" ? 2 : 1;
  return {columns.begin() + static_cast<std::ptrdiff_t>(first), columns.end()};
}

const ReportTable* ReportInputs::signal(const std::string& name) const {
  for (const auto& t : signals)
    if (t.name == name) return &t;
  return nullptr;
}

const ReportTable* ReportInputs::truth(const std::string& robot) const { return signal(robot + "/truth/state"); }

std::vector<std::string> ReportInputs::robots() const {
  std::vector<std::string> out;
  if (scenario["robots"] && scenario["robots"].IsMap())
    for (const auto& r : scenario["robots"]) out.push_back(r.first.Scalar());
  return out;
}

std::string ReportInputs::plant_type(const std::string& robot) const {
  const YAML::Node r = scenario["robots"] ? scenario["robots"][robot] : YAML::Node();
  if (r && r["plant"] && r["plant"]["type"] && r["plant"]["type"].IsScalar()) return r["plant"]["type"].Scalar();
  return "";
}

std::string ReportInputs::component_type(const std::string& component) const {
  if (scenario["services"] && scenario["services"][component] && scenario["services"][component]["type"])
    return scenario["services"][component]["type"].Scalar();
  return "";
}

bool ReportInputs::is_sensor(const ReportTable& t) const {
  if (t.robot.empty() || t.name.size() <= t.robot.size() + 1) return false;
  const YAML::Node r = scenario["robots"][t.robot];
  const std::string key = t.name.substr(t.robot.size() + 1);
  return r && r["sensors"] && r["sensors"].IsMap() && r["sensors"][key];
}

double ReportInputs::duration() const {
  return scenario["duration"] && scenario["duration"].IsScalar() ? scenario["duration"].as<double>() : 0.0;
}

ReportInputs read_report_inputs(const fs::path& run_dir) {
  const std::string dir = run_dir.string();
  if (!fs::is_directory(run_dir)) throw InputError(dir + ": no such run folder");
  // A run that did not reach its end has no metrics to report: say how it ended.
  if (const std::string status = run_folder_status(run_dir); !status.empty() && status != "complete")
    throw InputError(dir + ": the run did not complete (" + status + "): nothing to report");
  for (const char* f : {"metrics.json", "scenario.resolved.yaml"})
    if (!fs::is_regular_file(run_dir / f)) throw InputError(dir + ": not a run folder (no " + f + ")");
  ReportInputs in;
  in.dir = run_dir;
  {
    std::ifstream file(run_dir / "metrics.json");
    in.metrics = nlohmann::ordered_json::parse(file, nullptr, false);
    if (in.metrics.is_discarded() || !in.metrics.is_object())
      throw InputError(dir + "/metrics.json: not a JSON object");
  }
  in.scenario = load_yaml_file((run_dir / "scenario.resolved.yaml").string());
  in.signals = read_tables(run_dir, "signals");
  if (in.signals.empty()) throw InputError(dir + ": not a run folder (no signals/*.csv)");
  in.series = read_tables(run_dir, "series");
  read_signal_index(run_dir, in.signals);
  std::sort(in.signals.begin(), in.signals.end(),
            [](const ReportTable& a, const ReportTable& b) { return a.name < b.name; });
  const std::vector<std::string> robots = in.robots();
  for (auto& t : in.signals) t.robot = robot_of(t.name, robots);
  // A signal whose unit is not declared (a measurement sensor without an IDL message)
  // measures its robot's state: a field named like one of the state's has its unit.
  for (auto& t : in.signals) {
    const ReportTable* truth = in.truth(t.robot);
    if (!truth || truth == &t) continue;
    for (std::size_t c = 1; c < t.columns.size(); ++c)
      if (!t.units[c] && t.columns[c] != "step") t.units[c] = truth->unit(t.columns[c]);
  }
  for (auto& t : in.series) {
    t.name = t.stem;
    if (t.columns.size() >= 2) t.units[1] = std::nullopt;
  }
  return in;
}

std::vector<std::vector<double>> read_columns(const ReportInputs& in, const ReportTable& t,
                                              const std::vector<int>& columns) {
  const fs::path file = in.dir / t.path;
  std::ifstream stream(file);
  if (!stream) throw InputError(file.string() + ": cannot open file");
  std::vector<std::vector<double>> out(columns.size());
  const int last = columns.empty() ? 0 : *std::max_element(columns.begin(), columns.end());
  std::string line;
  std::getline(stream, line);  // header
  std::vector<double> row(static_cast<std::size_t>(last));
  for (long n = 2; std::getline(stream, line); ++n) {
    if (line.empty()) continue;
    const char* p = line.data();
    const char* end = p + line.size();
    for (int c = 0; c < last; ++c) {
      const auto r = std::from_chars(p, end, row[static_cast<std::size_t>(c)]);
      const bool more = c < last - 1;
      if (r.ec != std::errc() || (more && (r.ptr == end || *r.ptr != ',')) || (!more && r.ptr != end && *r.ptr != ','))
        throw InputError(file.string() + ":" + std::to_string(n) + ": column " + std::to_string(c + 1) +
                         ": not a number");
      p = r.ptr == end ? end : r.ptr + 1;
    }
    for (std::size_t i = 0; i < columns.size(); ++i) out[i].push_back(row[static_cast<std::size_t>(columns[i] - 1)]);
  }
  return out;
}

}  // namespace plexus::scenario
