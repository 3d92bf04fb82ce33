#include "plexus/service/dds_options.hpp"

#include <set>

#include "plexus/base/comma_list.hpp"
#include "plexus/runtime/security_cli.hpp"

namespace plexus::scenario {

void ServiceDdsOptions::add_to(CLI::App& app) {
  app.add_option("--dds", dds, "DDS vendor: fast or cyclone");
  app.add_option("--domain", domain, "DDS domain id (0..232)")->check(CLI::Range(0, 232));
  app.add_option("--qos-file", qos_file, "QoS profiles (default deploy/qos.yaml)");
  app.add_option("--service", service,
                 "The process's name in heartbeats, logs and its DDS participant (default: the executable and the "
                 "robots or services it hosts, as plexus launch names it)");
  app.add_option("--interface", interface_address, "Address of the one interface DDS uses (default 127.0.0.1)");
  app.add_option("--peers", peers, "Comma-separated unicast discovery peers (default 127.0.0.1)");
  app.add_option(
      "--transport", transport,
      "auto (UDP), udp, or shm (Fast DDS: shared memory with same-host Fast DDS peers, else UDP) (default auto; "
      "docs/runtime.md, Transports)");
  app.add_option("--max-participants", max_participants,
                 "DDS participants of the domain one host may hold, which discovery probes on each peer; the same "
                 "for every process of a deployment (default 32; docs/runtime.md)")
      ->check(CLI::Range(1, kMaxParticipantsPerHost));
  app.add_option("--naming", naming,
                 "Topic and type names on the wire: plexus or ros2 (docs/ros2.md) (default plexus)");
  rt::add_security_options(app, security, identity, governance);
}

rt::ParticipantOptions ServiceDdsOptions::participant(const std::string& default_name,
                                                      const std::string& default_identity) const {
  rt::ParticipantOptions po;
  po.vendor = rt::parse_vendor(dds);
  po.domain_id = domain;
  po.name = service.empty() ? default_name : service;
  po.network.interface_address = interface_address;
  po.network.transport = rt::parse_transport(transport);
  po.network.max_participants_per_host = max_participants;
  po.naming = rt::parse_naming(naming);
  const std::vector<std::string> listed = split_comma_list(peers);
  const std::set<std::string> unique(listed.begin(), listed.end());
  po.network.peers.assign(unique.begin(), unique.end());
  po.security = rt::security_from_options(security, identity, governance, default_identity);
  return po;
}

rt::QosProfiles ServiceDdsOptions::profiles() const {
  return rt::QosProfiles::load(qos_file.empty() ? rt::default_qos_file() : qos_file);
}

}  // namespace plexus::scenario
