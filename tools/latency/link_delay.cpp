// link_delay: a fixed delay on a link, in userspace, for kernels without the netem qdisc
// (this machine's: CONFIG_NET_SCH_NETEM and nftables' queue are not built). Runs in a middle
// network namespace between two veth ends and relays every Ethernet frame from one to the
// other after --delay-ms, both ways, in arrival order (docs/qos-bench.md, "Delay").
//
//   link_delay --a veth_a --b veth_b --delay-ms 5
//
// Frames are read with AF_PACKET sockets (ETH_P_ALL; the ones this program sends are not
// read back) into a ring of fixed slots allocated at start, and sent on the other interface
// when due. One thread: ppoll with a timeout until the next frame is due. A frame that finds
// the ring full, or is larger than a slot, is dropped and counted. SIGTERM ends it; it
// prints what it relayed.
#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "plexus/base/cli_style.hpp"
#include "plexus/base/clock.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

constexpr std::size_t kSlotBytes = 2048;  // a 1500-byte MTU frame and its header

int open_on(const std::string& ifname) {
  const int fd = socket(AF_PACKET, SOCK_RAW | SOCK_NONBLOCK, htons(ETH_P_ALL));
  if (fd < 0) throw std::runtime_error("socket(AF_PACKET): " + std::string(std::strerror(errno)));
  const unsigned index = if_nametoindex(ifname.c_str());
  if (index == 0) throw std::runtime_error("no interface '" + ifname + "'");
  sockaddr_ll addr{};
  addr.sll_family = AF_PACKET;
  addr.sll_protocol = htons(ETH_P_ALL);
  addr.sll_ifindex = static_cast<int>(index);
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0)
    throw std::runtime_error("bind to '" + ifname + "': " + std::strerror(errno));
  const int one = 1;  // not the frames this program sends on it
  if (setsockopt(fd, SOL_PACKET, PACKET_IGNORE_OUTGOING, &one, sizeof one) != 0)
    throw std::runtime_error("PACKET_IGNORE_OUTGOING: " + std::string(std::strerror(errno)));
  return fd;
}

/// A veth hands its peer UDP frames with the checksum left to the hardware (checksum
/// offload: the field holds only the pseudo-header's sum); a packet socket reads them so, and
/// sent on as they are they fail the receiver's check. IPv4 lets a UDP datagram go without a
/// checksum (0): the field of every IPv4 UDP header (a datagram's first fragment) is zeroed.
void clear_udp_checksum(unsigned char* frame, std::size_t n) {
  constexpr std::size_t kEth = 14;
  if (n < kEth + 20 || frame[12] != 0x08 || frame[13] != 0x00) return;  // not IPv4
  const unsigned char* ip = frame + kEth;
  const std::size_t ihl = static_cast<std::size_t>(ip[0] & 0x0f) * 4;
  const bool first_fragment = ((ip[6] & 0x1f) | ip[7]) == 0;
  if (ip[9] != 17 || !first_fragment || n < kEth + ihl + 8) return;  // not UDP's header
  frame[kEth + ihl + 6] = frame[kEth + ihl + 7] = 0;
}

/// Frames waiting for their time, oldest first: one ring per direction, so a direction's
/// frames leave in the order they came.
struct Ring {
  explicit Ring(std::size_t slots) : data(slots * kSlotBytes), length(slots), due(slots) {}
  std::vector<unsigned char> data;
  std::vector<std::size_t> length;
  std::vector<int64_t> due;
  std::size_t head = 0, count = 0;
  unsigned char* slot(std::size_t i) { return data.data() + (i % length.size()) * kSlotBytes; }
  bool full() const { return count == length.size(); }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"link_delay: relays frames between two interfaces after a fixed delay (docs/qos-bench.md)"};
  app.set_version_flag("--version", std::string("link_delay") + " " + PLEXUS_VERSION);
  std::string a, b;
  double delay_ms = 5;
  std::size_t slots = 8192;
  app.add_option("--a", a, "one interface")->required();
  app.add_option("--b", b, "the other")->required();
  app.add_option("--delay-ms", delay_ms, "delay each way, ms")->check(CLI::Range(0.0, 10000.0));
  app.add_option("--slots", slots, "frames held at once per direction")->check(CLI::Range(16, 1 << 20));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plexus::parse_error_exit(app, e, "link_delay");
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  int fd[2];
  try {
    fd[0] = open_on(a);
    fd[1] = open_on(b);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "link_delay: error: %s\n", e.what());
    return 1;
  }
  const int64_t delay_ns = static_cast<int64_t>(delay_ms * 1e6);
  Ring ring[2] = {Ring(slots), Ring(slots)};  // ring[i]: frames read on fd[i], to go out on the other
  long relayed = 0, dropped = 0;
  pollfd p[2] = {{fd[0], POLLIN, 0}, {fd[1], POLLIN, 0}};
  while (!g_stop) {
    const int64_t now = plexus::monotonic_ns();
    int64_t next = now + 100'000'000;  // wake at least every 100 ms to see a stop
    for (int d = 0; d < 2; ++d) {
      Ring& r = ring[d];
      while (r.count > 0 && r.due[r.head % slots] <= now) {
        const std::size_t i = r.head % slots;
        if (send(fd[1 - d], r.slot(i), r.length[i], 0) < 0)
          ++dropped;
        else
          ++relayed;
        ++r.head;
        --r.count;
      }
      if (r.count > 0) next = std::min(next, r.due[r.head % slots]);
    }
    const int64_t wait = std::max<int64_t>(0, next - plexus::monotonic_ns());
    const timespec timeout{static_cast<time_t>(wait / 1'000'000'000), static_cast<long>(wait % 1'000'000'000)};
    if (ppoll(p, 2, &timeout, nullptr) < 0 && errno != EINTR) break;
    for (int d = 0; d < 2; ++d) {
      if (!(p[d].revents & POLLIN)) continue;
      Ring& r = ring[d];
      for (;;) {  // every frame waiting on this socket
        unsigned char* into = r.full() ? nullptr : r.slot(r.head + r.count);
        unsigned char scratch[kSlotBytes];
        const ssize_t n = recv(fd[d], into ? into : scratch, kSlotBytes, MSG_TRUNC);
        if (n < 0) break;
        if (!into || static_cast<std::size_t>(n) > kSlotBytes) {
          ++dropped;
          continue;
        }
        const std::size_t i = (r.head + r.count) % slots;
        clear_udp_checksum(into, static_cast<std::size_t>(n));
        r.length[i] = static_cast<std::size_t>(n);
        r.due[i] = plexus::monotonic_ns() + delay_ns;
        ++r.count;
      }
    }
  }
  std::printf("{\"relayed\": %ld, \"dropped\": %ld}\n", relayed, dropped);
  return 0;
}
