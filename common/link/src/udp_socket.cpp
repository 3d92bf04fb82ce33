// The UDP transport: one socket bound to our address and connected to the device's, so the
// kernel filters out datagrams from anyone else and send() needs no address.
#include "plexus/link/udp_socket.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace plexus::link {
namespace {

std::string to_text(const UdpEndpoint& e) { return e.address + ":" + std::to_string(e.port); }

bool to_sockaddr(const UdpEndpoint& e, sockaddr_in& a) {
  a = sockaddr_in{};
  a.sin_family = AF_INET;
  a.sin_port = htons(e.port);
  return ::inet_pton(AF_INET, e.address.c_str(), &a.sin_addr) == 1;
}

// `err` is the errno of the failed call, taken before the message is built (allocating
// may change errno).
int fail(int fd, int err, const std::string& what, std::string& error) {
  error = what + ": " + std::strerror(err);
  if (fd >= 0) ::close(fd);
  return -1;
}

}  // namespace

bool parse_endpoint(const std::string& text, const std::string& what, UdpEndpoint& out, std::string& error) {
  const auto bad = [&](const std::string& why) {
    error = what + ": '" + text + "' " + why + " (expected IPV4:PORT, e.g. 127.0.0.1:5000)";
    return false;
  };
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos) return bad("has no port");
  const std::string address = text.substr(0, colon);
  const std::string port = text.substr(colon + 1);
  in_addr a{};
  if (address.empty() || ::inet_pton(AF_INET, address.c_str(), &a) != 1)
    return bad("has no valid IPv4 address ('" + address + "')");
  // Digits only (no sign, no spaces, no hex), at most 5 of them, then the range.
  long value = 0;
  bool digits = !port.empty() && port.size() <= 5;
  for (char c : port) {
    if (c < '0' || c > '9')
      digits = false;
    else
      value = value * 10 + (c - '0');
  }
  if (!digits || value < 1 || value > 65535) return bad("has no valid port 1..65535 ('" + port + "')");
  out.address = address;
  out.port = static_cast<uint16_t>(value);
  return true;
}

int open_udp(const UdpEndpoint& local, const UdpEndpoint& peer, std::string& error) {
  sockaddr_in l{}, p{};
  if (!to_sockaddr(local, l)) return fail(-1, EINVAL, "udp " + to_text(local) + ": not an IPv4 address", error);
  if (!to_sockaddr(peer, p)) return fail(-1, EINVAL, "udp " + to_text(peer) + ": not an IPv4 address", error);
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    const int err = errno;
    return fail(-1, err, "udp " + to_text(local) + ": cannot create a socket", error);
  }
  // A restarted bridge can bind its port again at once.
  const int one = 1;
  if (::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) != 0) {
    const int err = errno;
    return fail(fd, err, "udp " + to_text(local) + ": cannot set SO_REUSEADDR", error);
  }
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&l), sizeof l) != 0) {
    const int err = errno;
    return fail(fd, err, "udp " + to_text(local) + ": cannot bind", error);
  }
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&p), sizeof p) != 0) {
    const int err = errno;
    return fail(fd, err, "udp " + to_text(local) + ": cannot connect to " + to_text(peer), error);
  }
  return fd;
}

}  // namespace plexus::link
