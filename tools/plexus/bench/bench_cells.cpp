#include "bench/bench_cells.hpp"

#include <algorithm>

#include "bench/bench_runner.hpp"
#include "bench/bench_stats.hpp"

namespace plexus::cli::bench {
using Json = nlohmann::ordered_json;

Json cell_keys(const Group& g, int size, double loss, double delay_ms) {
  return {{"id", cell_id(g.pair_name(), g.transport, g.profile, size, g.topology)},
          {"pair", g.pair_name()},
          {"writer_dds", rt::to_string(g.pair.writer)},
          {"reader_dds", rt::to_string(g.pair.reader)},
          {"transport", g.transport},
          {"profile", g.profile},
          {"reliability", rt::to_string(g.qos.reliability)},
          {"size", size},
          {"topology", g.topology},
          {"loss_percent", g.topology == "two_ns" ? loss : 0.0},
          {"delay_ms", g.topology == "two_ns" ? delay_ms : 0.0}};
}

/// Why a group cannot run, or "".
std::string not_applicable(const Group& g, const std::string& topology_problem) {
  if (!topology_problem.empty()) return topology_problem;
  if (g.transport == "shm") {
    if (g.pair.writer != rt::Vendor::fast || g.pair.reader != rt::Vendor::fast)
      return "shared memory carries samples between Fast DDS participants only (Cyclone DDS 0.10 as Debian "
             "builds it has none; docs/runtime.md, Transports)";
    if (g.topology == "two_ns") return "two hosts share no memory";
  }
  return "";
}

Json cell_of(const Group& g, int size, const std::vector<GroupRun>& runs, const Matrix& m, bool first_size) {
  Json c = cell_keys(g, size, m.loss_percent, m.delay_ms);
  c["status"] = "ok";
  c["reason"] = "";
  // On one host both ends read one clock: the measured offset is shown, not applied (it is
  // the method's own error). Across the namespaces it is applied, as across hosts.
  double offset = 0;
  for (const auto& r : runs) offset += r.offset_us / static_cast<double>(runs.size());
  const double applied = g.topology == "two_ns" ? offset : 0.0;
  Json latency = Json::array();
  auto percent = [](const SizeResult::Cpu& used) {
    return Json{{"writer", used.wall_s > 0 ? 100 * used.writer_s / used.wall_s : 0.0},
                {"reader", used.wall_s > 0 ? 100 * used.reader_s / used.wall_s : 0.0}};
  };
  auto range = [](const std::vector<double>& v) {
    return v.size() > 1 ? *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end()) : 0.0;
  };
  const double headline = m.headline_rate();
  Json cpu_at_headline, spread_at_headline;
  for (double rate : m.rates_hz) {
    std::vector<double> oneway, rtt;
    long sent = 0, received = 0;
    double oneway_spread = 0, rtt_spread = 0;
    SizeResult::Cpu cpu;
    std::vector<double> p50s_oneway, p50s_rtt;
    for (const auto& r : runs) {
      const SizeResult& s = r.sizes.at(size);
      std::vector<double> ow = s.oneway_raw_us.count(rate) ? s.oneway_raw_us.at(rate) : std::vector<double>{};
      for (double& x : ow) x -= applied;
      const std::vector<double>& rt_us = s.rtt_us.count(rate) ? s.rtt_us.at(rate) : std::vector<double>{};
      oneway_spread = std::max(oneway_spread, median_spread(ow));
      rtt_spread = std::max(rtt_spread, median_spread(rt_us));
      p50s_oneway.push_back(distribution(ow)["p50"].get<double>());
      p50s_rtt.push_back(distribution(rt_us)["p50"].get<double>());
      oneway.insert(oneway.end(), ow.begin(), ow.end());
      rtt.insert(rtt.end(), rt_us.begin(), rt_us.end());
      sent += s.sent.count(rate) ? s.sent.at(rate) : 0;
      received += s.received.count(rate) ? s.received.at(rate) : 0;
      if (s.cpu.count(rate)) {
        const auto& c1 = s.cpu.at(rate);
        cpu = {cpu.writer_s + c1.writer_s, cpu.reader_s + c1.reader_s, cpu.wall_s + c1.wall_s};
      }
    }
    // Between chunks of each run, and between the runs.
    oneway_spread = std::max(oneway_spread, range(p50s_oneway));
    rtt_spread = std::max(rtt_spread, range(p50s_rtt));
    // Late: a sample that arrives after the next one is due (one-way latency over the period).
    long late = 0;
    if (rate > 0)
      for (double x : oneway) late += x > 1e6 / rate;
    latency.push_back({{"rate_hz", rate},
                       {"one_way_us", distribution(oneway)},
                       {"round_trip_us", distribution(rtt)},
                       {"sent", sent},
                       {"received", received},
                       {"lost", std::max(0L, sent - received)},
                       {"late", late},
                       {"cpu_percent", percent(cpu)},
                       {"spread", {{"one_way_p50_us", oneway_spread}, {"round_trip_p50_us", rtt_spread}}}});
    if (rate == headline || cpu_at_headline.is_null()) {
      cpu_at_headline = latency.back()["cpu_percent"];
      spread_at_headline = latency.back()["spread"];
    }
  }
  c["latency"] = latency;
  long f_sent = 0, f_recv = 0;
  double f_bytes = 0, f_window = 0, f_wall = 0;
  std::vector<double> rates_per_run;
  SizeResult::Cpu flood_cpu;
  for (const auto& r : runs) {
    const SizeResult& s = r.sizes.at(size);
    f_sent += s.flood_sent;
    f_recv += s.flood_received;
    f_bytes += s.flood_bytes;
    f_window += s.flood_window_s;
    f_wall += s.flood_wall_s;
    if (s.flood_window_s > 0) rates_per_run.push_back(static_cast<double>(s.flood_received) / s.flood_window_s);
    flood_cpu = {flood_cpu.writer_s + s.flood_cpu.writer_s, flood_cpu.reader_s + s.flood_cpu.reader_s,
                 flood_cpu.wall_s + s.flood_cpu.wall_s};
  }
  c["throughput"] = m.throughput_seconds > 0 && f_window > 0
                        ? Json{{"samples_per_s", static_cast<double>(f_recv) / f_window},
                               {"mb_per_s", f_bytes / f_window / 1e6},
                               {"sent", f_sent},
                               {"received", f_recv},
                               {"lost", std::max(0L, f_sent - f_recv)},
                               {"seconds", f_wall},
                               {"cpu_percent", percent(flood_cpu)}}
                        : Json(nullptr);
  // What the loop costs: the CPU at the summary's rate (each rate's is in its entry, the
  // saturation's in throughput).
  c["cpu_percent"] = cpu_at_headline;
  c["clock_offset_us"] = offset;
  c["clock_offset_applied"] = applied != 0.0;
  // Recovery and the QoS events are measured once per group: on its first size's cell.
  c["recovery"] = first_size && !runs.front().recovery.is_null() ? runs.front().recovery : Json(nullptr);
  Json events = {{"deadline", nullptr}, {"liveliness", nullptr}};
  if (first_size && g.qos.deadline_s > 0)
    events["deadline"] = {{"period_s", g.qos.deadline_s}, {"detected_after_s", runs.front().deadline_after}};
  if (first_size && g.qos.liveliness_lease_s > 0)
    events["liveliness"] = {{"lease_s", g.qos.liveliness_lease_s}, {"detected_after_s", runs.front().liveliness_after}};
  c["events"] = events;
  // The summary's rate's spreads (what --baseline compares), and the throughput's between runs.
  c["spread"] = spread_at_headline;
  c["spread"]["throughput_samples_per_s"] = range(rates_per_run);
  c["vendor_tool"] = nullptr;
  c["ratio"] = nullptr;
  return c;
}

}  // namespace plexus::cli::bench
