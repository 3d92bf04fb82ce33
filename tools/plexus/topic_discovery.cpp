#include "topic_discovery.hpp"

#include <algorithm>
#include <cctype>
#include <csignal>
#include <set>
#include <stdexcept>
#include <thread>

#include "plexus/base/clock.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/runtime/security_cli.hpp"
#include "plexus/runtime/vendor.hpp"

namespace plexus::cli {

std::atomic<bool> g_stop{false};

namespace {
void stop_waiting_on_signal(int) { g_stop = true; }
}  // namespace

void install_stop_handler() {
  std::signal(SIGINT, stop_waiting_on_signal);
  std::signal(SIGTERM, stop_waiting_on_signal);
}

void add_dds_options(CLI::App* app, DdsOptions& o) {
  app->add_option("--dds", o.dds, "DDS vendor: fast or cyclone")->capture_default_str();
  app->add_option("--domain", o.domain, "DDS domain id (0..232)")->capture_default_str()->check(CLI::Range(0, 232));
  app->add_option("--interface", o.interface_address, "address of the one interface DDS uses")->capture_default_str();
  app->add_option("--peers", o.peers, "comma-separated unicast discovery peers")->capture_default_str();
  app->add_option("--transport", o.transport, "auto, udp or shm (docs/runtime.md, Transports)")->capture_default_str();
  app->add_option("--naming", o.naming, "topic and type names on the wire: plexus or ros2 (docs/ros2.md)")
      ->capture_default_str();
  app->add_option("--max-participants", o.max_participants,
                  "DDS participants of the domain one host may hold, as the deployment's (docs/runtime.md)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxParticipantsPerHost));
  rt::add_security_options(*app, o.security, o.identity, o.governance);
}

std::unique_ptr<rt::Participant> make_participant(const DdsOptions& o, const std::string& name,
                                                  const std::string& identity) {
  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(o.dds);
  po.domain_id = o.domain;
  po.name = name;
  po.network.interface_address = o.interface_address;
  po.network.transport = rt::parse_transport(o.transport);
  po.network.max_participants_per_host = o.max_participants;
  po.naming = rt::parse_naming(o.naming);
  po.network.peers = split_comma_list(o.peers);
  po.security = rt::security_from_options(o.security, o.identity, o.governance, identity);
  init_logging(name, "", "warn");  // tools print their own output; only problems are logged
  return rt::Participant::create(po);
}

std::vector<rt::DiscoveredEndpoint> remote_endpoints(const rt::Participant& p, double wait_s) {
  const int64_t end = monotonic_ns() + static_cast<int64_t>(wait_s * 1e9);
  while (!g_stop && monotonic_ns() < end) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::vector<rt::DiscoveredEndpoint> out;
  for (auto& e : p.discovered_endpoints())
    if (!e.local) out.push_back(std::move(e));
  return out;
}

const msg::TypeSupport& resolve_topic_type(const rt::Participant& p, const std::string& topic,
                                           const std::string& type_option, double wait_s,
                                           std::vector<rt::EndpointQos>* writers) {
  const msg::TypeSupport* forced = nullptr;
  if (!type_option.empty()) {
    forced = msg::find_type_support(type_option);
    if (!forced) forced = msg::find_type_support("plexus::msg::" + type_option);
    if (!forced) {
      std::string known;
      for (const auto* ts : msg::all_type_supports()) known += (known.empty() ? "" : ", ") + std::string(ts->type_name);
      throw InputError("--type: unknown message type '" + type_option + "' (known: " + known + ")");
    }
  }
  const int64_t end = monotonic_ns() + static_cast<int64_t>(wait_s * 1e9);
  std::string announced;
  for (;;) {
    writers->clear();
    for (const auto& e : p.discovered_endpoints()) {
      if (e.local || !e.is_writer || e.topic != topic) continue;
      writers->push_back(e.qos);
      announced = e.type_name;
    }
    if (!writers->empty() || g_stop || monotonic_ns() >= end) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // IDL names are case-insensitive (docs/architecture.md): Pose2D and pose2d are one type.
  const auto same_type = [](const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
  };
  if (forced && !writers->empty() && !same_type(announced, forced->type_name))
    throw InputError("--type " + std::string(forced->type_name) + ": the writers of '" + topic + "' publish " +
                     announced + " (leave --type out to read them)");
  if (forced) return *forced;
  if (writers->empty())
    throw std::runtime_error("no writer on topic '" + topic + "' after " + std::to_string(wait_s).substr(0, 4) +
                             " s (give --type to subscribe anyway, or a longer --wait)");
  const msg::TypeSupport* ts = msg::find_type_support(announced);
  if (!ts)
    throw std::runtime_error("topic '" + topic + "' has type '" + announced +
                             "', which this plexus build does not know");
  return *ts;
}

rt::QosProfile subscriber_qos(const std::string& qos_file, const std::string& profile,
                              const std::vector<rt::EndpointQos>& writers, int32_t depth) {
  if (!profile.empty()) return rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file).get(profile);
  return rt::reader_qos_matching(writers, depth);
}

nlohmann::ordered_json qos_to_json(const rt::EndpointQos& q) {
  nlohmann::ordered_json j;
  j["reliability"] = rt::to_string(q.reliability);
  j["durability"] = q.durability_stronger ? "transient" : rt::to_string(q.durability);
  if (q.history_known) {
    j["history"] = rt::to_string(q.history);
    j["depth"] = q.depth;
  }
  j["deadline_s"] = q.deadline_s;
  j["liveliness"] = rt::to_string(q.liveliness);
  j["liveliness_lease_s"] = q.liveliness_lease_s;
  j["lifespan_s"] = q.lifespan_s;
  j["latency_budget_s"] = q.latency_budget_s;
  j["ownership"] = q.exclusive_ownership ? "exclusive" : "shared";
  j["data_representation"] = q.data_representation;
  return j;
}

}  // namespace plexus::cli
