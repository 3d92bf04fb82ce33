#include "fast_security.hpp"

namespace plexus::rt::detail {

void apply_fast_security(eprosima::fastdds::dds::DomainParticipantQos& qos, const SecurityOptions& s) {
  if (!s.enabled) return;
  auto& props = qos.properties().properties();
  const auto set = [&props](const std::string& name, const std::string& value) { props.emplace_back(name, value); };
  const std::string auth = "dds.sec.auth.builtin.PKI-DH.";
  const std::string access = "dds.sec.access.builtin.Access-Permissions.";
  set("dds.sec.auth.plugin", "builtin.PKI-DH");
  set(auth + "identity_ca", "file://" + s.identity_ca);
  set(auth + "identity_certificate", "file://" + s.certificate);
  set(auth + "private_key", "file://" + s.private_key);
  set("dds.sec.access.plugin", "builtin.Access-Permissions");
  set(access + "permissions_ca", "file://" + s.permissions_ca);
  set(access + "governance", "file://" + s.governance);
  set(access + "permissions", "file://" + s.permissions);
  set("dds.sec.crypto.plugin", "builtin.AES-GCM-GMAC");
}

}  // namespace plexus::rt::detail
