// How DDS samples travel between processes of one host (docs/runtime.md, Transports).
//
//   auto  plexus's choice, the default: Fast DDS's shared-memory transport between Fast DDS
//         participants of one host, UDPv4 to everything else; Cyclone DDS on UDPv4 (as
//         `shm`, without Cyclone's line on stderr). UDP until 2026-11-30: a 500 Hz serial
//         bridge's samples stalled for about 330 ms when a reader joined, Fast DDS 2.9's port
//         health check, now bounded (fast_participant.cpp, docs/runtime.md).
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

/// True when a Fast DDS participant uses shared memory with its peers of this host (`auto`,
/// `shm`).
inline bool fast_shared_memory(Transport t) { return t != Transport::udp; }

}  // namespace plexus::rt
