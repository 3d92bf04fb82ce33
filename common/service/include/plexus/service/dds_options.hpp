// The DDS options every service executable takes (service_main, the bridges), so that
// `plexus launch` can start any of them the same way and a user learns them once.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "plexus/runtime/participant.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::scenario {

struct ServiceDdsOptions {
  std::string dds = "fast";
  int domain = 0;
  std::string qos_file;  ///< empty: deploy/qos.yaml
  std::string service;   ///< participant and heartbeat name; empty: the caller's default
  std::string interface_address = "127.0.0.1";
  std::string peers = "127.0.0.1";
  std::string transport = "auto";                      ///< auto | udp | shm (plexus/runtime/transport.hpp)
  std::string naming = "plexus";                       ///< plexus | ros2 (plexus/runtime/naming.hpp)
  int max_participants = kDefaultParticipantsPerHost;  ///< rt::NetworkOptions::max_participants_per_host
  std::string security;                                ///< PKI folder: DDS Security on (docs/security.md); empty: off
  std::string identity;    ///< identity in <security>/identities, or a folder; empty: the default
  std::string governance;  ///< governance document; empty: <security>/governance.p7s

  /// --dds, --domain, --qos-file, --service, --interface, --peers, --transport,
  /// --max-participants, --naming, --security, --identity, --governance.
  void add_to(CLI::App& app);
  /// The participant: vendor, domain, network, security; named `service`, else
  /// `default_name`; identity `identity`, else `default_identity`. Throws InputError for a bad
  /// vendor, transport or naming or bad security material (one line naming the option and the file).
  rt::ParticipantOptions participant(const std::string& default_name, const std::string& default_identity) const;
  rt::QosProfiles profiles() const;
};

}  // namespace plexus::scenario
