#pragma once
// How many DDS participants of one domain a host may hold (docs/runtime.md, "Participants per
// host"): each takes a free RTPS participant id below the limit, and discovery probes that
// many ids on each peer. Shared by the runtime (rt::NetworkOptions) and the scenario's
// `dds.participants_per_host`, which `plexus launch` raises when a host runs more processes.

namespace plexus {

inline constexpr int kDefaultParticipantsPerHost = 32;
/// The RTPS ports of a domain leave room for 120: participant p's user unicast port is
/// 7400 + 250 d + 11 + 2 p, below the next domain's 7400 + 250 (d + 1).
inline constexpr int kMaxParticipantsPerHost = 120;

}  // namespace plexus
