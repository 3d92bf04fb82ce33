#include "bench/bench_report_figures.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "external_program.hpp"
#include "plexus/scenario/format.hpp"

namespace plexus::cli::bench_report_impl {
using plexus::scenario::format_number;
namespace {

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
    if (us > 0 && tail > 0) rows += format_number(us) + ' ' + format_number(tail) + '\n';
  }
  return rows;
}

/// One-way latency of each ok cell of a size and topology as its tail (1 - CDF), log-log: the
/// tail is spread out over decades instead of squashed against 1.
std::optional<Figure> cdf_figure(const json& run, const Axes& axes, double size, const std::string& topology) {
  const auto rate = summary_rate(run);
  Figure f{"cdf_" + format_number(size) + "_" + file_part(topology), "cdf", "", "", "", {}};
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
  for (double s : sizes) tics += (tics.empty() ? "" : ", ") + gp_quote(size_text(s)) + " " + format_number(s);
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
      rows += format_number(size) + ' ' + format_number(mb) + '\n';
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
      size_tics(sizes) + "set xrange [" + format_number(sizes.front() / 1.5) + ":" + format_number(sizes.back() * 1.5) +
      "]\n";
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
    if (*hz == 0) unpaced = format_number(unpaced_x) + ' ' + format_number(*p50) + ' ' + format_number(*p99) + '\n';
  }
  if (paced.empty() && unpaced.empty()) return "";
  std::sort(paced.begin(), paced.end());
  std::string rows;
  for (const auto& [hz, p50, p99] : paced)
    rows += format_number(hz) + ' ' + format_number(p50) + ' ' + format_number(p99) + '\n';
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
  for (double hz : rates) tics += gp_quote(shown(hz)) + " " + format_number(hz) + ", ";
  tics += "'unpaced' " + format_number(unpaced_x);
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
      tics + ")\nset xrange [" + format_number(slowest / 2) + ":" + format_number(unpaced_x * 2) + "]\n" +
      "set arrow from " + format_number(split) + ", graph 0 to " + format_number(split) +
      ", graph 1 nohead dt 3 lc rgb '#888888'\n";
  return f;
}

}  // namespace

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

}  // namespace plexus::cli::bench_report_impl
