#include "plexus/runtime/vendor.hpp"

#include <string>

#include "plexus/base/input_error.hpp"

namespace plexus::rt {

Vendor parse_vendor(std::string_view name, std::string_view origin) {
  if (name == "fast" || name == "fastdds") return Vendor::fast;
  if (name == "cyclone" || name == "cyclonedds") return Vendor::cyclone;
  throw InputError(std::string(origin) + ": unknown DDS vendor '" + std::string(name) + "' (expected fast or cyclone)");
}

const char* to_string(Vendor v) { return v == Vendor::fast ? "fast" : "cyclone"; }

}  // namespace plexus::rt
