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

  /// --dds, --domain, --qos-file, --service, --interface, --peers.
  void add_to(CLI::App& app);
  /// The participant: vendor, domain, network; named `service`, else `default_name`.
  /// Throws InputError for a bad vendor.
  rt::ParticipantOptions participant(const std::string& default_name) const;
  rt::QosProfiles profiles() const;
};

}  // namespace plexus::scenario
