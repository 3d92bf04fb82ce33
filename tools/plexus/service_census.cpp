#include "service_census.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "plexus/msg/fixed_text.hpp"
#include "service_state.hpp"

namespace plexus::cli {
namespace {

using msg::text_of;

/// Heartbeats, the launcher's lockstep clock and plexus param: every process has them, they say nothing of its data.
bool internal_topic(const std::string& t) {
  return t.rfind("health/", 0) == 0 || t.rfind("lockstep/", 0) == 0 || t.rfind("param/", 0) == 0;
}

}  // namespace

void ServiceCensus::heartbeat(const std::string& topic, const msg::Heartbeat& hb, int64_t receive_ns) {
  auto& s = by_topic_[topic];
  // A new pid (a restart) or a new run (fewer loops): the rate starts again from this one.
  if (s.beats == 0 || hb.pid() != s.last.pid() || hb.loop_count() < s.last.loop_count()) {
    s.first = hb;
    s.beats = 0;
  }
  s.last = hb;
  s.last_receive_ns = receive_ns;
  ++s.beats;
}

nlohmann::ordered_json ServiceCensus::rows(const std::vector<rt::DiscoveredEndpoint>& endpoints, int64_t now_ns) const {
  struct Row {
    std::map<std::string, std::string> out, in;  // topic -> type
    std::string health_topic;
  };
  std::map<std::string, Row> by_name;
  for (const auto& e : endpoints) {
    if (e.local) continue;
    Row& r = by_name[e.participant];
    if (e.is_writer && e.topic.rfind("health/", 0) == 0) r.health_topic = e.topic;
    if (internal_topic(e.topic)) continue;
    (e.is_writer ? r.out : r.in)[e.topic] = e.type_name;
  }
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& [name, r] : by_name) {
    const auto space = name.find(' ');
    nlohmann::ordered_json j;
    j["name"] = name;
    j["executable"] = name.substr(0, space);
    std::vector<std::string> hosted;  // the robots or services its name says it hosts
    if (space != std::string::npos) {
      std::string rest = name.substr(space + 1);
      for (std::size_t at = 0; at <= rest.size();) {
        const auto comma = std::min(rest.find(',', at), rest.size());
        if (comma > at) hosted.push_back(rest.substr(at, comma - at));
        at = comma + 1;
      }
    }
    j["hosts"] = hosted;
    const auto seen = by_topic_.find(r.health_topic);
    if (!r.health_topic.empty() && seen != by_topic_.end()) {
      const Seen& s = seen->second;
      const auto& hb = s.last;
      j["host"] = text_of(hb.host());
      j["pid"] = hb.pid();
      j["state"] = state_name(hb.state());
      j["uptime_s"] = hb.uptime_s();
      const double span =
          static_cast<double>(hb.header().publish_time_ns() - s.first.header().publish_time_ns()) * 1e-9;
      if (s.beats >= 2 && span > 0)
        j["loop_hz"] = static_cast<double>(hb.loop_count() - s.first.loop_count()) / span;
      else
        j["loop_hz"] = nullptr;  // one heartbeat seen: no rate yet
      j["loops"] = hb.loop_count();
      j["compute_p99_us"] = hb.compute_p99_us();
      j["jitter_p99_us"] = hb.jitter_p99_us();
      j["heartbeat_age_s"] = static_cast<double>(now_ns - s.last_receive_ns) * 1e-9;
      j["heartbeat_topic"] = r.health_topic;
    } else {
      j["host"] = nullptr;
      j["state"] = nullptr;  // no heartbeat: a tool, or a process in a lockstep run
    }
    nlohmann::ordered_json out = nlohmann::ordered_json::array(), in = nlohmann::ordered_json::array();
    for (const auto& [t, ty] : r.out) out.push_back({{"topic", t}, {"type", ty}});
    for (const auto& [t, ty] : r.in) in.push_back({{"topic", t}, {"type", ty}});
    j["out"] = out;
    j["in"] = in;
    list.push_back(std::move(j));
  }
  return list;
}

}  // namespace plexus::cli
