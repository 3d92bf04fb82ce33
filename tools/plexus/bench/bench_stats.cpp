#include "bench/bench_stats.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace plexus::cli::bench {

std::vector<double> read_samples_us(const std::string& path, double offset_us) {
  std::vector<double> v;
  if (path.empty()) return v;
  std::ifstream f(path);
  for (long long ns; f >> ns;) v.push_back(static_cast<double>(ns) * 1e-3 - offset_us);
  return v;
}

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size() - 1, k == 0 ? 0 : k - 1)];
}

nlohmann::ordered_json distribution(const std::vector<double>& us) {
  std::vector<double> s = us;
  std::sort(s.begin(), s.end());
  nlohmann::ordered_json cdf = nlohmann::ordered_json::array();
  // Points dense in the tail: fractions 1 - 10^-x for x from 0.05 to 3 (to p99.9), then the max.
  if (!s.empty()) {
    double last = -1;
    for (int i = 1; i <= 60; ++i) {
      const double frac = i == 60 ? 1.0 : 1.0 - std::pow(10.0, -3.0 * i / 59.0);
      if (frac <= last) continue;
      last = frac;
      cdf.push_back({quantile(s, frac), frac});
    }
  }
  return {{"count", s.size()},
          {"p50", quantile(s, 0.5)},
          {"p90", quantile(s, 0.9)},
          {"p99", quantile(s, 0.99)},
          {"p999", quantile(s, 0.999)},
          {"max", s.empty() ? 0.0 : s.back()},
          {"cdf", cdf}};
}

double median_spread(const std::vector<double>& us, int chunks) {
  const std::size_t n = us.size() / static_cast<std::size_t>(chunks);
  if (chunks < 2 || n < 10) return 0;
  double lo = 1e300, hi = -1e300;
  for (int c = 0; c < chunks; ++c) {
    std::vector<double> part(us.begin() + static_cast<std::ptrdiff_t>(c * n),
                             us.begin() + static_cast<std::ptrdiff_t>((c + 1) * n));
    std::sort(part.begin(), part.end());
    const double m = quantile(part, 0.5);
    lo = std::min(lo, m);
    hi = std::max(hi, m);
  }
  return hi - lo;
}

}  // namespace plexus::cli::bench
