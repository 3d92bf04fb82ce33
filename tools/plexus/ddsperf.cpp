#include "ddsperf.hpp"

#include <algorithm>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace plexus::cli {

std::string ddsperf_uri(const std::string& interface, const std::vector<std::string>& peers) {
  std::string peer_list;
  for (const auto& p : peers) peer_list += "<Peer address=\"" + p + "\"/>";
  return "CYCLONEDDS_URI=<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface address=\"" + interface +
         "\"/></Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><ParticipantIndex>auto</"
         "ParticipantIndex><MaxAutoParticipantIndex>31</MaxAutoParticipantIndex><Peers>" +
         peer_list + "</Peers></Discovery></Domain></CycloneDDS>";
}

nlohmann::ordered_json parse_ddsperf_ping(const std::string& out) {
  static const std::regex line_re(
      R"(size (\d+) mean ([0-9.]+)us min ([0-9.]+)us 50% ([0-9.]+)us 90% ([0-9.]+)us 99% ([0-9.]+)us max ([0-9.]+)us cnt (\d+))");
  double n = 0, mean = 0, p50 = 0, p90 = 0, p99 = 0, mx = 0;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, line_re)) continue;
    const double c = std::stod(m[8]);
    n += c;
    mean += c * std::stod(m[2]);
    p50 += c * std::stod(m[4]);
    p90 += c * std::stod(m[5]);
    p99 += c * std::stod(m[6]);
    mx = std::max(mx, std::stod(m[7]));
  }
  if (n <= 0) throw std::runtime_error("ddsperf printed no latency lines");
  // Half round trips -> round trips (x2), to compare like with like.
  return {{"implementation", "ddsperf"},
          {"received", static_cast<int>(n)},
          {"rtt_mean_us", 2 * mean / n},
          {"rtt_p50_us", 2 * p50 / n},
          {"rtt_p90_us", 2 * p90 / n},
          {"rtt_p99_us", 2 * p99 / n},
          {"rtt_max_us", 2 * mx},
          {"note", "ddsperf reports half round trips per second; shown x2, count-weighted over its 1 s intervals"}};
}

nlohmann::ordered_json parse_ddsperf_sub(const std::string& out) {
  static const std::regex line_re(R"(lost (\d+) rate ([0-9.]+) kS/s ([0-9.]+) Mb/s)");
  nlohmann::ordered_json best;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, line_re)) continue;
    const double rate = std::stod(m[2]) * 1e3;
    if (!best.is_null() && rate <= best["samples_per_s"].get<double>()) continue;
    best = {{"samples_per_s", rate}, {"mb_per_s", std::stod(m[3]) / 8.0}, {"lost", std::stol(m[1])}};
  }
  return best;
}

}  // namespace plexus::cli
