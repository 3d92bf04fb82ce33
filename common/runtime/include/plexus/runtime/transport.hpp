// How DDS samples travel between processes of one host (docs/runtime.md, Transports).
//
//   auto  plexus's choice, the default: UDPv4 on both vendors. Fast DDS's shared memory is
//         not the default: with it, a 500 Hz serial bridge's samples stalled for about 330 ms
//         when a reader matched (bridges.balancing_contract_serial_fast failed 10 of 17 runs,
//         over UDP 0 of 6; docs/runtime.md, Transports).
//   udp   UDPv4 only, on both vendors: every sample crosses the loopback interface.
//   shm   Fast DDS: its shared-memory transport between Fast DDS participants of one host
//         (UDPv4 to everything else: other hosts, Cyclone DDS peers). RTPS messages as over
//         UDP, copied through a shared segment instead of the loopback interface; no data
//         sharing (fast_participant.cpp says why). Cyclone DDS cannot carry plexus's samples
//         over iceoryx (docs/runtime.md says why), so a Cyclone participant says so on
//         stderr once and stays on UDP.
#pragma once

#include <string_view>

namespace plexus::rt {

enum class Transport { automatic, udp, shm };

/// "auto", "udp" or "shm"; anything else throws InputError naming `origin` (the option or
/// file:line it came from).
Transport parse_transport(std::string_view name, std::string_view origin = "--transport");
const char* to_string(Transport t);

/// True when a Fast DDS participant uses shared memory with its peers of this host (`shm`).
inline bool fast_shared_memory(Transport t) { return t == Transport::shm; }

}  // namespace plexus::rt
