#include "bench/bench_report.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "bench/bench_report_csv.hpp"
#include "bench/bench_report_figures.hpp"
#include "bench/bench_report_html.hpp"

namespace plexus::cli::bench_report_impl {
namespace {

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
