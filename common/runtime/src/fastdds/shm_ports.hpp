// A Fast DDS participant id whose shared-memory port no running writer still holds.
//
// Why (docs/runtime.md, Transports): Fast DDS 2.9's SHM transport gives a participant the
// port of its user unicast locator (7411 + 250 d + 2 p, DDSI-RTPS 9.6.1.1), a segment
// /dev/shm/fastrtps_port<N> with a lock file fastrtps_port<N>_el that its one listener holds.
// A process killed with SIGKILL leaves both behind ("zombie": the file there, its lock free).
// Its restarted process, with its UDP ports free again, gets the same participant id and so
// the same port; Fast DDS then removes the zombie segment and creates a new one
// (SharedMemGlobal::open_port_internal), but does not mark the old one broken, so a writer
// that had opened the port before the kill keeps pushing into the removed segment and the
// new reader never hears from it (upstream eProsima/Fast-DDS PR 4728, not in 2.9). Measured
// with tests/fault/restarted_reader.sh over the SHM transport alone: 4 of 10 restarted
// readers got 12-13 samples and then nothing.
//
// The workaround: plexus looks first at the port Fast DDS would take by itself (the first one
// from participant 0 that no live listener holds). Only when some process still maps that
// port's zombie segment does plexus give Fast DDS an explicit participant id, the first whose
// port is free or a zombie nobody maps (a zombie nobody maps is harmless: Fast DDS resets it).
// Otherwise Fast DDS chooses as it always does: explicit ids of processes starting in the
// same instant collided and then lost samples at start (2 of 13 main jobs), which Fast DDS's
// own choice never did (0 of 16). The choice and the participant's creation run under a
// host-wide lock (ShmParticipantLock), so two plexus processes do not pick at once.
#pragma once

#include <cstdint>
#include <string>

namespace plexus::rt::detail {

/// What the SHM port `port` is on this host (Fast DDS's default SHM domain name, "fastrtps").
enum class ShmPortState {
  absent,  ///< no lock file: never opened, or closed cleanly
  live,    ///< its listener holds the lock
  zombie,  ///< lock file left by a dead listener, and no process maps the segment
  held,    ///< lock file left by a dead listener, and some process still maps the segment
};
ShmPortState shm_port_state(uint32_t port, const std::string& shm_dir = "/dev/shm");

/// RTPS port parameters (Fast DDS's `PortParameters`): base, domain gain, participant gain,
/// offset of the user unicast port (d3).
struct RtpsPorts {
  uint32_t base = 7400, domain_gain = 250, participant_gain = 2, offset_d3 = 11;
};

/// The participant id to give Fast DDS on `domain`: -1 (Fast DDS chooses) unless the SHM port
/// Fast DDS would take by itself is a zombie that some process maps; then the lowest id in
/// [0, limit) whose SHM port is absent or a zombie nobody maps (-1 if none).
int pick_shm_participant_id(uint32_t domain, int limit, const RtpsPorts& ports = {},
                            const std::string& shm_dir = "/dev/shm");

/// Removes the shared-memory segments that Fast DDS participants of dead processes left
/// behind: `fastrtps_<16 hex digits>` (a participant's segment, 0.5 MiB by default) whose lock
/// file `..._el` no live process holds and which no process maps, with that lock file. Fast
/// DDS 2.9 unlinks its segment only when the participant closes, so every SIGKILLed or crashed
/// process leaves its segment in /dev/shm (tmpfs: memory) until `fastdds shm clean` runs.
/// Ports (`fastrtps_port<N>`) are not touched: Fast DDS resets a zombie port itself, and
/// pick_shm_participant_id keeps off one still held. Returns how many segments it removed.
int remove_zombie_segments(const std::string& shm_dir = "/dev/shm");

/// An exclusive lock on `shm_dir`/plexus_fastdds_participants.lock while it lives: held from
/// the choice above until Fast DDS has opened the participant's ports. Without the file (no
/// permission), no lock.
class ShmParticipantLock {
 public:
  explicit ShmParticipantLock(const std::string& shm_dir = "/dev/shm");
  ~ShmParticipantLock();
  ShmParticipantLock(const ShmParticipantLock&) = delete;
  ShmParticipantLock& operator=(const ShmParticipantLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace plexus::rt::detail
