// Shared by `plexus topic`, `record`, `replay`: DDS options, waiting for discovery,
// resolving a topic's type at run time, QoS as JSON, Ctrl-C.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "plexus/base/comma_list.hpp"
#include "plexus/runtime/discovery.hpp"
#include "plexus/runtime/participant.hpp"

namespace plexus::cli {

struct DdsOptions {
  std::string dds = "fast";
  int domain = 0;
  std::string interface_address = "127.0.0.1";         ///< the one interface DDS uses
  std::string peers = "127.0.0.1";                     ///< comma-separated unicast discovery peers
  std::string transport = "auto";                      ///< auto | udp | shm (plexus/runtime/transport.hpp)
  std::string naming = "plexus";                       ///< plexus | ros2 (plexus/runtime/naming.hpp)
  int max_participants = kDefaultParticipantsPerHost;  ///< rt::NetworkOptions::max_participants_per_host
  std::string security, identity, governance;          ///< DDS Security (plexus/runtime/security_cli.hpp)
};
void add_dds_options(CLI::App* app, DdsOptions& o);
/// A participant named `name`; under --security its identity is --identity, else `identity`
/// (the tool's own: plexus_topic, plexus_record, plexus_replay).
std::unique_ptr<rt::Participant> make_participant(const DdsOptions& o, const std::string& name,
                                                  const std::string& identity);

/// Set by SIGINT/SIGTERM once install_stop_handler() ran.
extern std::atomic<bool> g_stop;
void install_stop_handler();

/// Remote endpoints (not this participant's), after waiting `wait_s` for discovery.
std::vector<rt::DiscoveredEndpoint> remote_endpoints(const rt::Participant& p, double wait_s);

/// The type of `topic`: `type_option` if given (InputError if unknown), else the type its
/// writers announce, waiting up to `wait_s` for one to be discovered. Fills `writers` with
/// the QoS of the writers seen. Throws InputError for an unknown --type, runtime_error if
/// no writer shows up or the announced type is not one plexus knows.
const msg::TypeSupport& resolve_topic_type(const rt::Participant& p, const std::string& topic,
                                           const std::string& type_option, double wait_s,
                                           std::vector<rt::EndpointQos>* writers);

/// The QoS profile for a subscriber: `profile` from the QoS file if given, else one that
/// matches the discovered writers (see rt::reader_qos_matching).
rt::QosProfile subscriber_qos(const std::string& qos_file, const std::string& profile,
                              const std::vector<rt::EndpointQos>& writers, int32_t depth);

/// A discovered endpoint's QoS as plexus record stores it (read back by replay_plan.cpp's
/// recorded_qos).
nlohmann::ordered_json qos_to_json(const rt::EndpointQos& q);

}  // namespace plexus::cli
