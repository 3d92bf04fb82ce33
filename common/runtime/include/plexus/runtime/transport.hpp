// How DDS samples travel between processes of one host (docs/runtime.md, Transports).
//
//   auto  plexus's choice, the default: UDPv4 on both vendors. Fast DDS's shared memory is
//         not the default because a process SIGKILLed while it held one of its interprocess
//         mutexes aborted a peer ("Interprocess mutex timeout when locking. Possible deadlock:
//         owner died without unlocking?", fault.kill_each_service_fast; docs/runtime.md).
//   udp   UDPv4 only, on both vendors: every sample crosses the loopback interface.
//   shm   Fast DDS: its shared-memory transport between Fast DDS participants of one host
//         (UDPv4 to everything else: other hosts, Cyclone DDS peers), and data sharing for
//         volatile endpoints of plain (fixed-size) types: a reader of the same host reads the
//         sample in the writer's pool. Cyclone DDS cannot carry plexus's samples over iceoryx
//         (docs/runtime.md says why), so a Cyclone participant says so on stderr once and
//         stays on UDP.
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
