// DDS Security on a Fast DDS 2.9 participant: its builtin plugins, configured by properties.
#pragma once

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

#include "plexus/runtime/security.hpp"

namespace plexus::rt::detail {

/// Adds the properties that load Fast DDS's builtin plugins (PKI-DH, Access-Permissions,
/// AES-GCM-GMAC) with the files of `s`. No-op when security is off.
void apply_fast_security(eprosima::fastdds::dds::DomainParticipantQos& qos, const SecurityOptions& s);

}  // namespace plexus::rt::detail
