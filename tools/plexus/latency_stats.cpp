#include "latency_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "external_program.hpp"
#include "plexus/base/input_error.hpp"

namespace plexus::cli {

Percentiles percentiles(std::vector<double>& v) {
  Percentiles p;
  p.count = v.size();
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  double sum = 0;
  for (double x : v) sum += x;
  p.mean = sum / static_cast<double>(v.size());
  auto at = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, k == 0 ? 0 : k - 1)];
  };
  p.p50 = at(0.50);
  p.p90 = at(0.90);
  p.p99 = at(0.99);
  p.max = v.back();
  return p;
}

Percentiles histogram_percentiles(const std::vector<double>& counts) {
  Percentiles p;
  double total = 0, sum = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    total += counts[i];
    sum += counts[i] * static_cast<double>(i);
    if (counts[i] > 0) p.max = static_cast<double>(i);
  }
  p.count = static_cast<std::size_t>(total);
  if (total <= 0) return p;
  p.mean = sum / total;
  auto at = [&](double q) {
    const double want = std::ceil(q * total);
    double acc = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
      acc += counts[i];
      if (acc >= want) return static_cast<double>(i);
    }
    return p.max;
  };
  p.p50 = at(0.50);
  p.p90 = at(0.90);
  p.p99 = at(0.99);
  return p;
}

std::string ratio_text(double a, double b) {
  if (!(b > 0) || !(a >= 0)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", a / b);
  return buf;
}

void write_histogram_png(const std::string& png, const std::string& title, const std::vector<Series>& series) {
  if (find_program("gnuplot").empty()) throw std::runtime_error("gnuplot not found (install gnuplot-nox)");
  // x range: up to 1.5 x the largest p99, so the tail does not squash the body.
  double xmax = 1;
  for (const auto& s : series) {
    if (s.bucketed) {
      xmax = std::max(xmax, histogram_percentiles(s.values).p99 * 1.5);
    } else {
      auto copy = s.values;
      xmax = std::max(xmax, percentiles(copy).p99 * 1.5);
    }
  }
  const double width = std::max(xmax / 60.0, 0.05);
  std::string plot;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string dat = png + ".dat" + std::to_string(i);
    std::ofstream f(dat);
    if (!f) throw std::runtime_error("cannot write " + dat);
    const auto& s = series[i];
    if (s.bucketed) {
      for (std::size_t k = 0; k < s.values.size(); ++k)
        if (s.values[k] > 0) f << k << ' ' << s.values[k] << '\n';
    } else {
      for (double x : s.values) f << x << " 1\n";
    }
    plot +=
        std::string(i ? ", " : "") + "'" + dat + "' using (bin($1)):2 smooth freq with boxes title '" + s.name + "'";
  }
  const std::string gp = png + ".gp";
  {
    std::ofstream g(gp);
    if (!g) throw std::runtime_error("cannot write " + gp);
    g << "set terminal pngcairo size 900,500 noenhanced\n"
      << "set output '" << png << "'\n"
      << "set title '" << title << "'\n"
      << "set xlabel 'microseconds'\nset ylabel 'samples'\nset logscale y\nset grid\nset style fill transparent solid "
         "0.4 noborder\n"
      << "set xrange [0:" << xmax << "]\n"
      << "w = " << width << "\nset boxwidth w\nbin(x) = w * floor(x / w) + w / 2\n"
      << "plot " << plot << "\n";
  }
  std::string out;
  if (run_program(find_program("gnuplot"), {gp}, out, {}, true) != 0)
    throw std::runtime_error("gnuplot failed on " + gp + ": " + out);
}

nlohmann::ordered_json pct_json(const Percentiles& p) {
  return {{"count", p.count}, {"mean_us", p.mean}, {"p50_us", p.p50},
          {"p90_us", p.p90},  {"p99_us", p.p99},   {"max_us", p.max}};
}

void print_compare(const char* what, const Percentiles& a, const Percentiles& b, const std::string& b_name,
                   bool b_has_p90) {
  std::printf("\n%s (us)      %12s %12s %8s\n", what, "plexus", b_name.c_str(), "ratio");
  const std::pair<const char*, std::pair<double, double>> rows[] = {{"mean", {a.mean, b.mean}},
                                                                    {"p50", {a.p50, b.p50}},
                                                                    {"p90", {a.p90, b_has_p90 ? b.p90 : -1}},
                                                                    {"p99", {a.p99, b.p99}},
                                                                    {"max", {a.max, b.max}}};
  for (const auto& [name, v] : rows) {
    if (v.second < 0)
      std::printf("  %-16s %12.1f %12s %8s\n", name, v.first, "n/a", "n/a");
    else
      std::printf("  %-16s %12.1f %12.1f %8s\n", name, v.first, v.second, ratio_text(v.first, v.second).c_str());
  }
}

void make_out_dir(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw InputError("--out: cannot create directory " + dir);
}

}  // namespace plexus::cli
