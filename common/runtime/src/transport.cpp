#include "plexus/runtime/transport.hpp"

#include <string>

#include "plexus/base/input_error.hpp"

namespace plexus::rt {

Transport parse_transport(std::string_view name, std::string_view origin) {
  if (name == "auto") return Transport::automatic;
  if (name == "udp") return Transport::udp;
  if (name == "shm") return Transport::shm;
  throw InputError(std::string(origin) + ": unknown transport '" + std::string(name) + "' (expected auto, udp or shm)");
}

const char* to_string(Transport t) {
  switch (t) {
    case Transport::udp: return "udp";
    case Transport::shm: return "shm";
    case Transport::automatic: break;
  }
  return "auto";
}

}  // namespace plexus::rt
