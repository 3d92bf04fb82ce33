// The DDS vendor, chosen at run time.
#pragma once

#include <string>
#include <string_view>

namespace plexus::rt {

enum class Vendor { fast, cyclone };

/// "fast" or "cyclone" (also "fastdds", "cyclonedds"); anything else throws InputError
/// naming `origin` (the option or file:line it came from).
Vendor parse_vendor(std::string_view name, std::string_view origin = "--dds");
const char* to_string(Vendor v);

}  // namespace plexus::rt
