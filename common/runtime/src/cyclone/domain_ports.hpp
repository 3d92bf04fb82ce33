// A Cyclone DDS domain whose sockets stay off the other domains' discovery ports.
//
// Why (docs/runtime.md, "Domains on one host"): Cyclone DDS 0.10 sends from a socket bound to
// "any port" and also reads RTPS messages from it (q_init.c: the transmit connection;
// q_receive.c: it joins the receive thread's wait set). On Linux that port comes from the
// ephemeral range 32768-60999, which holds the well-known ports of domains 102-213
// (DDSI-RTPS 2.3, 9.6.1.1: 7400 + 250 d + 10 + 2 p). When it lands on the unicast discovery
// port of a participant p of another domain d, every Fast DDS participant of domain d
// announces itself there (plexus's unicast peers list every participant port of its domain),
// Fast DDS 2.9 sends no domain id in that announcement, so Cyclone DDS takes it for one of
// its own domain, and Fast DDS in turn ignores the domain id of Cyclone's answer: the two
// domains see each other's topics and exchange samples. Reproduced deterministically by
// tests/scripts/adjacent_domains.sh (interop.adjacent_domains_mixed).
#pragma once

#include <dds/dds.h>

#include <map>
#include <string>

namespace plexus::rt::detail {

/// True when `port` is the unicast discovery port of some participant (index 0-119) of a
/// domain (0-232) other than `domain`, with the RTPS default port parameters both vendors use.
bool is_foreign_discovery_port(unsigned port, unsigned domain);

/// The local ports of this process's UDP sockets (IPv4 and IPv6), by socket inode, read from
/// /proc/self/fd and /proc/self/net/udp{,6}. Empty where /proc is not there.
std::map<unsigned long, unsigned> own_udp_ports();

/// dds_create_domain(domain, config), done again while one of the sockets it opened sits on
/// another domain's discovery port (is_foreign_discovery_port): each such port is held by a
/// placeholder socket until the domain is created elsewhere. After 16 tries it keeps the last
/// and says so on stderr. Returns what dds_create_domain returns.
dds_entity_t create_domain_off_foreign_ports(dds_domainid_t domain, const std::string& config);

}  // namespace plexus::rt::detail
