#include "run_result.hpp"

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "plexus/distributed/wire.hpp"
#include "plexus/evaluation/evaluation.hpp"
#include "plexus/evaluation/report.hpp"
#include "plexus/evaluation/run_folder.hpp"

namespace plexus::cli {

scenario::FieldUnits wire_field_units() {
  return [](const std::string& message, const std::string& field) -> std::optional<std::string> {
    const distributed::WireType* type = distributed::find_wire_type(message);
    if (!type) return std::nullopt;
    for (const auto& slot : type->slots)
      if (slot.field == field) return std::string(slot.unit);
    return std::nullopt;
  };
}

int finish_run(const scenario::Scenario& sc, const scenario::RunLog& log, double wall_seconds,
               const std::filesystem::path& dir, bool json, bool quiet, const RunSummary& summary) {
  const scenario::Evaluation ev = scenario::evaluate(sc, log);
  scenario::write_run_folder(dir, sc, log, ev, wall_seconds, wire_field_units());
  if (!summary.extra.empty()) std::ofstream(dir / "launch.json") << summary.extra.dump(2) << "\n";
  if (json) {
    nlohmann::ordered_json j = ev.to_json();
    for (const auto& [key, value] : summary.extra.items()) j[key] = value;
    std::cout << j.dump() << std::endl;
  } else {
    std::printf("%s\n", summary.headline.c_str());
    for (const auto& [name, r] : ev.metrics)
      std::printf("  %-24s %s\n", name.c_str(), scenario::format_number(r.value).c_str());
    std::printf("  %-24s %s\n", "digest", ev.digest.c_str());
    for (const auto& line : summary.lines) std::printf("  %s\n", line.c_str());
  }
  if (!quiet) std::fprintf(stderr, "run folder: %s\n", dir.string().c_str());
  for (const auto& f : ev.failures) std::fprintf(stderr, "%s\n", f.c_str());
  for (const auto& f : ev.inconsistent) std::fprintf(stderr, "%s\n", f.c_str());
  return ev.failures.empty() ? 0 : 1;
}

int interrupted_run(const std::string& command, int signal, const std::filesystem::path& dir, double wall_seconds) {
  const std::string name = signal == SIGINT    ? "SIGINT"
                           : signal == SIGTERM ? "SIGTERM"
                                               : "signal " + std::to_string(signal);
  scenario::mark_run_folder(dir, "interrupted (" + name + ")");
  std::fprintf(stderr, "%s: interrupted (%s) after %.1f s; run folder %s is incomplete (not scored)\n", command.c_str(),
               name.c_str(), wall_seconds, dir.string().c_str());
  return 128 + signal;
}

void log_scenario_warnings(const scenario::Scenario& sc, const std::filesystem::path& dir) {
  scenario::log_warnings(sc, " (details: " + (dir / "summary.md").string() + ")");
}

int print_report(const std::string& run_dir, bool to_stderr) {
  const auto r = scenario::write_report(run_dir);
  std::FILE* out = to_stderr ? stderr : stdout;
  std::fprintf(out, "\n%s\nreport: %s\n        %s\n", r.table.c_str(), r.html.string().c_str(),
               r.markdown.string().c_str());
  for (const auto& p : r.plots) std::fprintf(out, "  %s\n", p.string().c_str());
  return r.failed;
}

}  // namespace plexus::cli
