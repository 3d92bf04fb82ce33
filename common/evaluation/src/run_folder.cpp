#include "plexus/evaluation/run_folder.hpp"

#include <cstdio>
#include <ctime>
#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "plexus/base/input_error.hpp"
#include "plexus/scenario/format.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

std::ofstream open_out(const fs::path& p) {
  std::ofstream out(p);
  if (!out) throw InputError(p.string() + ": cannot write file");
  return out;
}

void write_signal_csv(const fs::path& p, const SignalTrace& trace, double base_step) {
  auto out = open_out(p);
  std::string line = "t,step";
  for (const auto& f : trace.spec.fields) line += "," + f;
  out << line << '\n';
  for (std::size_t row = 0; row < trace.size(); ++row) {
    line.clear();
    append_number(line, static_cast<double>(trace.steps[row]) * base_step);
    line += ',' + std::to_string(trace.steps[row]);
    for (std::size_t f = 0; f < trace.width(); ++f) {
      line += ',';
      append_number(line, trace.at(row, f));
    }
    out << line << '\n';
  }
}

void write_series_csv(const fs::path& p, const std::string& name, const MetricResult& r) {
  auto out = open_out(p);
  out << "t," << name << '\n';
  std::string line;
  for (const auto& [t, v] : r.series) {
    line.clear();
    append_number(line, t);
    line += ',';
    append_number(line, v);
    out << line << '\n';
  }
}

std::string fixed3(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string md_cell(const std::string& s) { return s.empty() ? "-" : s; }

void write_summary(const fs::path& p, const Scenario& sc, const Evaluation& ev, double wall_seconds) {
  auto out = open_out(p);
  out << "# Run of scenario `" << sc.name << "`\n\n";
  if (!sc.description.empty()) out << sc.description << "\n\n";
  out << "- scenario file: `" << sc.file << "`\n"
      << "- duration " << format_number(sc.duration) << " s, base step " << format_number(sc.step) << " s (" << sc.steps
      << " steps), seed " << sc.seed << "\n"
      << "- components: " << sc.components.size() << ", signals: " << sc.signals.size() << "\n"
      << "- wall time " << fixed3(wall_seconds) << " s";
  if (wall_seconds > 0) out << " (" << fixed3(sc.duration / wall_seconds) << "x real time)";
  out << "\n- digest `" << ev.digest << "`\n\n";
  out << "| metric | value | expectation | result |\n|---|---|---|---|\n";
  for (const auto& [name, r] : ev.metrics) {
    std::string bound, result;
    for (const auto& e : sc.expectations)
      if (e.metric == name) {
        bound += (bound.empty() ? "" : ", ") + std::string(e.op_text()) + " " + format_number(e.bound);
        result = worse_result(result, expectation_result(e, r.value));
      }
    out << "| " << name << " | " << format_number(r.value) << " | " << md_cell(bound) << " | " << md_cell(result)
        << " |\n";
  }
  out << "\n"
      << (ev.failures.empty() ? "All expectations met" : "Expectations failed:")
      << (ev.failures.empty() ? (ev.inconsistent.empty() ? "." : " but those inconsistent in the paper.") : "") << "\n";
  for (const auto& f : ev.failures) out << "\n- " << f;
  for (const auto& f : ev.inconsistent) out << "\n- " << f;
  out << "\n";
  if (!sc.warnings.empty()) {
    out << "\n## Warnings\n";
    for (const auto& w : sc.warnings) out << "\n- " << (w.detail.empty() ? w.text : w.detail) << "\n";
  }
}

/// signals.json: for each signal, its file, producer, IDL message and the unit of each field.
void write_signal_index(const fs::path& p, const RunLog& log, const FieldUnits& units) {
  nlohmann::ordered_json index = nlohmann::ordered_json::object();
  for (const auto& trace : log.signals) {
    const SignalSpec& spec = trace.spec;
    nlohmann::ordered_json field_units = nlohmann::ordered_json::object();
    for (const auto& f : spec.fields) {
      const std::optional<std::string> unit = units && !spec.message.empty() ? units(spec.message, f) : std::nullopt;
      field_units[f] = unit ? nlohmann::ordered_json(*unit) : nlohmann::ordered_json(nullptr);
    }
    index[spec.name] = {{"file", "signals/" + signal_file_name(spec.name)},
                        {"producer", spec.producer},
                        {"message", spec.message},
                        {"units", std::move(field_units)}};
  }
  open_out(p) << index.dump(2) << '\n';
}

}  // namespace

fs::path default_run_folder(const std::string& scenario_name) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &utc);
  return fs::path("runs") / (scenario_name + "-" + stamp);
}

bool is_run_folder(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir / kRunStatusFile, ec)) return true;
  // Written before run folders carried a status file: the files every run folder has.
  return fs::exists(dir / "scenario.resolved.yaml", ec) && fs::exists(dir / "metrics.json", ec);
}

fs::path prepare_run_folder(const std::string& out, const std::string& scenario_name, const std::string& suffix) {
  std::error_code ec;
  fs::path dir;
  if (!out.empty()) {
    dir = out;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      throw InputError("--out " + out + ": exists and is not a folder");
    if (fs::exists(dir, ec) && !fs::is_empty(dir, ec)) {
      // An earlier run's folder is emptied so that nothing of that run mixes into this one's
      // report; anything else is the user's and stays untouched.
      if (!is_run_folder(dir))
        throw InputError("--out " + out + ": the folder is not empty and is not a plexus run folder (choose another)");
      for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
      if (ec) throw InputError("--out " + out + ": cannot empty the earlier run's folder: " + ec.message());
    }
    fs::create_directories(dir, ec);
    if (ec) throw InputError("--out " + out + ": cannot create the folder: " + ec.message());
  } else {
    // runs/<scenario>-<UTC time>: create_directory is atomic, so two runs started in the same
    // second (or at once) get two folders, the later one with -2, -3, ...
    const fs::path base = default_run_folder(scenario_name).string() + suffix;
    fs::create_directories(base.parent_path(), ec);
    for (int n = 1; n <= 1000 && dir.empty(); ++n) {
      const fs::path candidate = n == 1 ? base : fs::path(base.string() + "-" + std::to_string(n));
      if (fs::create_directory(candidate, ec))
        dir = candidate;
      else if (ec)
        throw InputError(candidate.string() + ": cannot create the run folder: " + ec.message());
    }
    if (dir.empty()) throw InputError(base.string() + ": 1000 run folders of this name already exist");
  }
  mark_run_folder(dir, "running");
  return dir;
}

void mark_run_folder(const fs::path& dir, const std::string& status) {
  open_out(dir / kRunStatusFile) << status << '\n';
}

std::string run_folder_status(const fs::path& dir) {
  std::ifstream in(dir / kRunStatusFile);
  std::string line;
  if (!in || !std::getline(in, line)) return is_run_folder(dir) ? "complete" : "";
  return line;
}

std::string signal_file_name(const std::string& signal) {
  std::string s = signal;
  for (char& c : s)
    if (c == '/') c = '.';
  return s + ".csv";
}

void write_run_folder(const fs::path& dir, const Scenario& scenario, const RunLog& log, const Evaluation& evaluation,
                      double wall_seconds, const FieldUnits& units) {
  std::error_code ec;
  fs::create_directories(dir / "signals", ec);
  if (!ec) fs::create_directories(dir / "series", ec);
  if (ec) throw InputError(dir.string() + ": cannot create the run folder: " + ec.message());

  {
    auto out = open_out(dir / "scenario.resolved.yaml");
    YAML::Emitter em;
    em << scenario.resolved;
    out << "# Resolved from " << scenario.file << " (after --set, derived seeds written in)\n" << em.c_str() << '\n';
  }
  for (const auto& trace : log.signals)
    write_signal_csv(dir / "signals" / signal_file_name(trace.spec.name), trace, log.base_step);
  for (const auto& [name, r] : evaluation.metrics)
    if (!r.series.empty()) write_series_csv(dir / "series" / (name + ".csv"), name, r);
  write_signal_index(dir / "signals.json", log, units);
  open_out(dir / "metrics.json") << evaluation.to_json().dump(2) << '\n';
  write_summary(dir / "summary.md", scenario, evaluation, wall_seconds);
  mark_run_folder(dir, "complete");
}

}  // namespace plexus::scenario
