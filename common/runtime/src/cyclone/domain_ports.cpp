// A Cyclone DDS domain whose sockets stay off the other domains' discovery ports
// (domain_ports.hpp says why).
#include "domain_ports.hpp"

#include <dirent.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace plexus::rt::detail {
namespace {

// DDSI-RTPS 2.3, 9.6.1.1: PB, DG, PG and d1, the defaults of both vendors (plexus changes none).
constexpr unsigned kPortBase = 7400, kDomainGain = 250, kParticipantGain = 2, kUnicastDiscoveryOffset = 10;
constexpr unsigned kMaxDomain = 232;
constexpr unsigned kMaxParticipantIndex = (kDomainGain - kUnicastDiscoveryOffset) / kParticipantGain - 1;  // 119
constexpr int kTries = 16;

// Inodes of this process's sockets.
std::vector<unsigned long> own_socket_inodes() {
  std::vector<unsigned long> inodes;
  DIR* dir = opendir("/proc/self/fd");
  if (dir == nullptr) return inodes;
  while (const dirent* e = readdir(dir)) {
    char target[64];
    const std::string link = std::string("/proc/self/fd/") + e->d_name;
    const ssize_t n = readlink(link.c_str(), target, sizeof target - 1);
    if (n <= 0) continue;
    target[n] = '\0';
    unsigned long inode = 0;
    if (std::sscanf(target, "socket:[%lu]", &inode) == 1) inodes.push_back(inode);
  }
  closedir(dir);
  return inodes;
}

// Appends inode -> local port of every socket in a /proc/net/udp-format table.
void read_udp_table(const char* path, std::map<unsigned long, unsigned>& ports) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string slot, local, remote, state, queues, timer, retransmits, uid, timeout;
    unsigned long inode = 0;
    if (!(f >> slot >> local >> remote >> state >> queues >> timer >> retransmits >> uid >> timeout >> inode)) continue;
    const auto colon = local.rfind(':');
    if (colon == std::string::npos) continue;
    char* end = nullptr;
    const unsigned long port = std::strtoul(local.c_str() + colon + 1, &end, 16);
    if (end == local.c_str() + colon + 1 || *end != '\0' || port > 65535) continue;  // not a port: skipped
    ports[inode] = static_cast<unsigned>(port);
  }
}

// A socket bound to `port` on every address, so that the kernel gives that port to no one else.
int hold_port(unsigned port) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) return -1;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_ANY);
  if (bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

bool is_foreign_discovery_port(unsigned port, unsigned domain) {
  if (port < kPortBase + kUnicastDiscoveryOffset) return false;
  const unsigned d = (port - kPortBase) / kDomainGain, offset = (port - kPortBase) % kDomainGain;
  if (d > kMaxDomain || d == domain || offset < kUnicastDiscoveryOffset) return false;
  const unsigned p = offset - kUnicastDiscoveryOffset;
  return p % kParticipantGain == 0 && p / kParticipantGain <= kMaxParticipantIndex;
}

std::map<unsigned long, unsigned> own_udp_ports() {
  std::map<unsigned long, unsigned> all, own;
  read_udp_table("/proc/self/net/udp", all);
  read_udp_table("/proc/self/net/udp6", all);
  for (unsigned long inode : own_socket_inodes())
    if (auto it = all.find(inode); it != all.end()) own.insert(*it);
  return own;
}

dds_entity_t create_domain_off_foreign_ports(dds_domainid_t domain, const std::string& config) {
  std::vector<int> held;
  dds_entity_t d = 0;
  for (int attempt = 1;; ++attempt) {
    const auto before = own_udp_ports();
    d = dds_create_domain(domain, config.c_str());
    if (d < 0) break;
    std::vector<unsigned> foreign;
    for (const auto& [inode, port] : own_udp_ports())
      if (!before.count(inode) && is_foreign_discovery_port(port, static_cast<unsigned>(domain)))
        foreign.push_back(port);
    if (foreign.empty()) break;
    if (attempt == kTries) {
      std::fprintf(stderr,
                   "plexus: Cyclone DDS domain %u: a socket still sits on port %u, another domain's discovery port, "
                   "after %d tries (docs/runtime.md, \"Domains on one host\")\n",
                   static_cast<unsigned>(domain), foreign.front(), kTries);
      break;
    }
    dds_delete(d);
    for (unsigned port : foreign)
      if (const int fd = hold_port(port); fd >= 0) held.push_back(fd);
  }
  for (int fd : held) close(fd);
  return d;
}

}  // namespace plexus::rt::detail
