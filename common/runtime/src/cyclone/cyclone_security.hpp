// DDS Security on a Cyclone DDS 0.10 participant: its builtin plugins, configured by
// participant QoS properties, so that each participant of a process has its own identity.
#pragma once

#include <dds/dds.h>

#include "plexus/runtime/security.hpp"

namespace plexus::rt::detail {

/// Adds the properties that load Cyclone's builtin plugins (authentication, access control,
/// cryptography) from the paths found at build time, with the files of `s`. No-op when
/// security is off.
void apply_cyclone_security(dds_qos_t* qos, const SecurityOptions& s);

}  // namespace plexus::rt::detail
