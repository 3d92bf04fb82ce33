// The Cyclone DDS domain's guard against another domain's discovery ports (domain_ports.hpp).
#include "cyclone/domain_ports.hpp"

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace plexus::rt::detail {
namespace {

// 7400 + 250 d + 10 + 2 p (DDSI-RTPS 2.3, 9.6.1.1).
unsigned discovery_port(unsigned d, unsigned p) { return 7400 + 250 * d + 10 + 2 * p; }

TEST(DomainPorts, AnotherDomainsParticipantDiscoveryPortIsForeign) {
  // The port of the forced collision in tests/scripts/adjacent_domains.sh and of the CI sighting.
  EXPECT_TRUE(is_foreign_discovery_port(discovery_port(105, 2), 138));
  EXPECT_TRUE(is_foreign_discovery_port(discovery_port(140, 0), 141));
  EXPECT_TRUE(is_foreign_discovery_port(discovery_port(0, 0), 1));
  EXPECT_TRUE(is_foreign_discovery_port(discovery_port(232, 119), 0));
}

TEST(DomainPorts, OwnDomainDataAndMulticastPortsAreNot) {
  EXPECT_FALSE(is_foreign_discovery_port(discovery_port(138, 2), 138));      // own domain
  EXPECT_FALSE(is_foreign_discovery_port(discovery_port(105, 2) + 1, 138));  // user data port (d3 = 11)
  EXPECT_FALSE(is_foreign_discovery_port(7400 + 250 * 105, 138));            // multicast discovery (d0)
  EXPECT_FALSE(is_foreign_discovery_port(7400 + 250 * 105 + 1, 138));        // multicast data (d2)
  EXPECT_FALSE(is_foreign_discovery_port(7409, 3));                          // below every domain's block
  EXPECT_FALSE(is_foreign_discovery_port(7400 + 250 * 233 + 10, 3));         // no domain 233
  EXPECT_FALSE(is_foreign_discovery_port(0, 3));
}

TEST(DomainPorts, OwnUdpPortsListsThisProcessesSocket) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  ASSERT_EQ(getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len), 0);
  const unsigned port = ntohs(a.sin_port);
  bool found = false;
  for (const auto& [inode, p] : own_udp_ports()) found = found || p == port;
  EXPECT_TRUE(found) << "port " << port;
  close(fd);
  for (const auto& [inode, p] : own_udp_ports()) EXPECT_NE(p, port);
}

}  // namespace
}  // namespace plexus::rt::detail
