// A UDP socket for the UDP bridge and the device emulator: bound to a local address and
// connected to the peer's, so it sends frames there and receives only the peer's datagrams.
#pragma once

#include <cstdint>
#include <string>

namespace plexus::link {

struct UdpEndpoint {
  std::string address;  ///< dotted IPv4
  uint16_t port = 0;
};

/// Parses "ADDR:PORT" (IPv4). False with `error` set to one line naming `what` otherwise.
bool parse_endpoint(const std::string& text, const std::string& what, UdpEndpoint& out, std::string& error);

/// A non-blocking, close-on-exec UDP socket bound to `local` and connected to `peer`.
/// Returns the fd, or -1 with `error` set to one line naming the address and the cause.
int open_udp(const UdpEndpoint& local, const UdpEndpoint& peer, std::string& error);

}  // namespace plexus::link
