// plexus service list: every running plexus process on a domain, as `ros2 node list` and
// `ros2 node info` would show it, built from discovery and the heartbeats alone (no launcher
// needed): name, host, state, uptime, loop rate, p99, heartbeat age, topics out and in
// (service_census.hpp; docs/tools.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <thread>

#include "command.hpp"
#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/msg/messages.hpp"
#include "plexus/runtime/vendor.hpp"
#include "service_census.hpp"
#include "topic_discovery.hpp"

namespace plexus::cli {
namespace {

struct ServiceOpts {
  DdsOptions dds;
  double wait = 3.0;  ///< s: discovery, and two heartbeats (once a second) for a loop rate
  bool json = false;
};

std::string opt_text(const nlohmann::ordered_json& v, const char* fmt) {
  if (v.is_null()) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v.get<double>());
  return buf;
}

int run_list(const ServiceOpts& o) {
  rt::parse_vendor(o.dds.dds);
  auto p = make_participant(o.dds, "plexus_service", "plexus_service");
  // A heartbeat reader for every health/ topic as it is discovered: best effort matches the
  // services' reliable writers and never holds them back.
  rt::QosProfile qos;
  qos.reliability = rt::QosProfile::Reliability::best_effort;
  qos.depth = 4;
  std::map<std::string, rt::Subscriber<msg::Heartbeat>> readers;
  const std::string heartbeat_type = msg::type_support<msg::Heartbeat>().type_name;
  ServiceCensus census;
  msg::Heartbeat hb;
  const int64_t end = monotonic_ns() + static_cast<int64_t>(o.wait * 1e9);
  while (!g_stop && monotonic_ns() < end) {
    for (const auto& e : p->discovered_endpoints())
      if (!e.local && e.is_writer && e.type_name == heartbeat_type && e.topic.rfind("health/", 0) == 0 &&
          !readers.count(e.topic))
        readers.emplace(e.topic, p->subscriber<msg::Heartbeat>(e.topic, qos));
    for (auto& [topic, r] : readers)
      while (r.take(hb)) census.heartbeat(topic, hb, monotonic_ns());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::vector<rt::DiscoveredEndpoint> remote;
  for (auto& e : p->discovered_endpoints())
    if (!e.local) remote.push_back(std::move(e));
  const auto rows = census.rows(remote, monotonic_ns());
  if (o.json) {
    std::printf("%s\n", rows.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace).c_str());
    return 0;
  }
  if (rows.empty()) {
    std::fprintf(stderr, "plexus service list: no plexus process discovered on domain %d in %.1f s\n", o.dds.domain,
                 o.wait);
    return 0;
  }
  int name_w = 7, host_w = 4;  // the columns as wide as their longest entry
  for (const auto& r : rows) {
    name_w = std::max(name_w, static_cast<int>(r["name"].get<std::string>().size()));
    if (r["host"].is_string()) host_w = std::max(host_w, static_cast<int>(r["host"].get<std::string>().size()));
  }
  std::printf("%-*s %-*s %-14s %9s %8s %9s %8s  %s\n", name_w, "service", host_w, "host", "state", "uptime s",
              "loop Hz", "p99 us", "beat s", "topics out | in");
  for (const auto& r : rows) {
    std::string out, in;
    for (const auto& t : r["out"]) out += (out.empty() ? "" : " ") + t["topic"].get<std::string>();
    for (const auto& t : r["in"]) in += (in.empty() ? "" : " ") + t["topic"].get<std::string>();
    const bool beats = !r["state"].is_null();
    std::printf("%-*s %-*s %-14s %9s %8s %9s %8s  %s | %s\n", name_w, r["name"].get<std::string>().c_str(), host_w,
                beats ? r["host"].get<std::string>().c_str() : "-",
                beats ? r["state"].get<std::string>().c_str() : "(no heartbeat)",
                beats ? opt_text(r["uptime_s"], "%.1f").c_str() : "-",
                beats ? opt_text(r["loop_hz"], "%.1f").c_str() : "-",
                beats ? opt_text(r["compute_p99_us"], "%.1f").c_str() : "-",
                beats ? opt_text(r["heartbeat_age_s"], "%.2f").c_str() : "-", out.empty() ? "-" : out.c_str(),
                in.empty() ? "-" : in.c_str());
  }
  return 0;
}

}  // namespace

Command add_service_command(CLI::App& root) {
  auto o = std::make_shared<ServiceOpts>();
  Command c;
  c.app = root.add_subcommand("service", "Inspect running plexus processes: list (either DDS vendor)");
  c.app->require_subcommand(1);
  auto* list = c.app->add_subcommand(
      "list", "Every plexus process on the domain: host, state, uptime, loop rate, p99, heartbeat age, topics");
  add_dds_options(list, o->dds);
  list->add_option("--wait", o->wait, "seconds to listen (discovery, and two heartbeats for a rate)")
      ->capture_default_str()
      ->check(positive_seconds());
  list->add_flag("--json", o->json, "JSON output: one array, a row per process");
  c.run = [o, list] {
    install_stop_handler();
    if (list->parsed()) return run_list(*o);
    return 2;
  };
  return c;
}

}  // namespace plexus::cli
