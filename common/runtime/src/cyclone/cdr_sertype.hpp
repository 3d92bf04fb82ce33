// Cyclone DDS sertype/serdata that carries plexus messages as their CDR bytes (internal).
//
// Cyclone normally serialises its own C structs (from idlc). plexus keeps one C++ type
// per message, so this sertype takes the type name (from the idlc descriptor) and the
// Fast CDR codec of the generated C++ class: a serdata is just the XCDR1 bytes,
// exactly what goes on the wire, and the same bytes Fast DDS produces.
#pragma once

#include <string>

#include <dds/dds.h>

#include "plexus/msg/type_support.hpp"

namespace plexus::rt::detail {

/// A new sertype for `type` (keyless topics), named `wire_name` on the wire (naming.hpp).
/// Consumed by dds_create_topic_sertype.
struct ddsi_sertype* make_cdr_sertype(const msg::TypeSupport& type, const std::string& wire_name);

/// A serdata holding `sample` (a T) serialised; write it with dds_writecdr.
struct ddsi_serdata* serdata_from_sample(const struct ddsi_sertype* type, const void* sample);

/// Decodes a serdata taken with dds_takecdr into `sample` (a T). False if malformed.
bool serdata_to_sample(const struct ddsi_serdata* d, void* sample);

}  // namespace plexus::rt::detail
