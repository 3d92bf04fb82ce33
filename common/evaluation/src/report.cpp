#include "plexus/evaluation/report.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "plexus/base/input_error.hpp"
#include "plexus/evaluation/report_comparison.hpp"
#include "plexus/evaluation/report_figures.hpp"
#include "plexus/evaluation/report_html.hpp"
#include "plexus/evaluation/report_inputs.hpp"

namespace plexus::scenario {
namespace fs = std::filesystem;
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw InputError(p.string() + ": cannot write file");
}

}  // namespace

Report write_report(const fs::path& run_dir) {
  const ReportInputs in = read_report_inputs(run_dir);
  const std::string dir = run_dir.string();
  fs::create_directories(run_dir / "plots");

  std::vector<Figure> figures = paper_figures(in);
  for (auto& f : signal_figures(in)) figures.push_back(std::move(f));
  write_file(run_dir / "plots" / "report.gp", gnuplot_script(figures));
  const std::string cmd = "cd " + shell_quote(dir) + " && gnuplot plots/report.gp 2> plots/gnuplot.log";
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("gnuplot failed (is gnuplot-nox installed?); see " + dir + "/plots/gnuplot.log");
  Report report;
  for (const auto& f : figures) {
    report.plots.push_back(run_dir / f.file);
    if (!fs::is_regular_file(report.plots.back()))
      throw std::runtime_error("gnuplot did not write " + report.plots.back().string());
  }

  const Comparison comparison = compare(in);
  report.table = comparison.markdown();
  report.failed = comparison.failed;

  std::ostringstream md;
  const std::string name = in.scenario["name"] && in.scenario["name"].IsScalar() ? in.scenario["name"].Scalar() : dir;
  md << "# Report: " << name << "\n\n";
  md << "Digest `"
     << (in.metrics.contains("digest") && in.metrics["digest"].is_string() ? in.metrics["digest"].get<std::string>()
                                                                           : "?")
     << "`\n\n";
  md << report.table;
  md << "\nThe same, with the papers' figures and every plot inline: report.html.\n\n## Plots\n";
  for (const auto& f : figures) md << "\n![" << f.title << "](" << f.file << ")\n";
  report.markdown = run_dir / "report.md";
  write_file(report.markdown, md.str());
  report.html = run_dir / "report.html";
  write_file(report.html, report_html(in, comparison, figures));
  return report;
}

}  // namespace plexus::scenario
