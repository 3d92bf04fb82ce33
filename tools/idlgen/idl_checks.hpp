// The rules that keep plexus messages interoperable between Fast DDS and Cyclone DDS and
// usable as signals (docs/architecture.md, "Messages and topics"; docs/sdk.md):
// - every struct is @final; no @optional, no @key (plexus topics are keyless);
// - no member named like a type, and no two members of one struct, equal ignoring case
//   (IDL identifiers are case-insensitive: fastddsgen rejects `Header header`);
// - strings and sequences are bounded;
// - @unit and @range only on numbers, min <= max, and within what the member's type holds;
// - [fields: ...] gives one entry per array element, names unique within the struct;
//   [count] only on an unsigned short member of a struct with arrays.
// Type objects and XCDR1 are the generators' options (plexus_add_messages), not the files'.
#pragma once

#include "idl_model.hpp"

namespace plexus::idlgen {

/// Throws IdlError (file:line: what) at the first file given on the command line that breaks a rule.
void check_model(const Model& model);

}  // namespace plexus::idlgen
