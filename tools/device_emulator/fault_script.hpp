// Scripted link faults (README.md "Faults"): parsed from --fault KIND@T[:key=value,...] and
// --faults FILE.yaml, then applied at their time by FaultInjector, from the emulator's loop.
//
//   flip@T:count=N       flip one random bit in each of the next N frames (encoded bytes)
//   drop@T:bytes=N       remove N bytes from the middle of the next frame
//   garbage@T:bytes=N    send N random bytes, zeros included
//   oversize@T:bytes=N   send N non-zero random bytes, then 0x00 (N >= kMaxEncodedFrame)
//   poison@T:count=N     the next N frames carry NaN (odd ones) or 1e300 (even ones) in
//                        their first field, with a valid CRC
//   stall@T:for=S        send nothing for S s (the plant runs on; its frames are discarded)
//   unplug@T:for=S       close the link, wait S s, open a new one
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "emulator_link.hpp"

namespace plexus::emulator {

enum class FaultKind { flip, drop, garbage, oversize, poison, stall, unplug };
const char* to_string(FaultKind kind);

struct Fault {
  FaultKind kind = FaultKind::flip;
  double at = 0.0;        ///< s since the start
  int64_t count = 1;      ///< flip, poison: frames
  std::size_t bytes = 0;  ///< drop, garbage, oversize
  double for_s = 0.0;     ///< stall, unplug
  std::string origin;     ///< "--fault flip@1" or "faults.yaml:3", for the log

  // Progress, set by FaultInjector.
  bool started = false;
  bool applied = false;      ///< it has happened in full (every frame it names, the whole stall)
  double started_at = -1.0;  ///< s since the start
  int64_t frames = 0;        ///< flip, poison, drop: frames changed so far
};

/// Parses one --fault SPEC. Throws InputError "--fault SPEC: ..." for an unknown kind or
/// key, a negative time, a bad number.
Fault parse_fault_spec(const std::string& spec);
/// Loads a --faults file: a YAML list of maps with the keys `kind`, `at` and the kind's
/// parameters (`count`, `bytes`, `for`). Throws InputError naming the file, line and key.
std::vector<Fault> load_fault_file(const std::string& path);

/// Applies the script. Everything is sized at construction; tick() and the frame hooks do
/// not allocate.
class FaultInjector {
 public:
  FaultInjector(std::vector<Fault> faults, uint64_t seed);

  /// Starts the faults due by `t` (s since the start, in script order), ends stalls and
  /// unplugs that are over, sends fault bytes. Call once per loop tick, before the step.
  void tick(double t, EmulatorLink& link);
  /// Whether frames go out now (not stalled, link open); if not, the caller discards them.
  bool sending(const EmulatorLink& link) const { return !stalled_ && link.is_open(); }
  /// Poisons the payload of an outgoing frame if a poison fault is active (before its CRC).
  void on_payload(uint8_t* payload, std::size_t n);
  /// Flips a bit or drops bytes in an encoded frame (delimiter included) if such a fault is
  /// active; returns its new length.
  std::size_t on_encoded(uint8_t* frame, std::size_t n);

  const std::vector<Fault>& faults() const { return faults_; }
  nlohmann::ordered_json summary() const;

 private:
  void start(Fault& f, double t, EmulatorLink& link);
  bool send_bytes(Fault& f, EmulatorLink& link);
  Fault* active(FaultKind kind);
  void finish_frame(Fault& f);

  std::vector<Fault> faults_;         // in time order (stable: script order within a time)
  std::size_t next_ = 0;              // first fault not started
  std::vector<std::size_t> waiting_;  // started, waiting to be done (frame faults; bytes while not sending)
  std::mt19937_64 rng_;
  std::vector<uint8_t> scratch_;  // garbage and oversize bytes
  bool stalled_ = false;
  double stall_until_ = 0.0;
  bool unplugged_ = false;
  double replug_at_ = 0.0;
  double next_retry_ = 0.0;
  RateLimiter log_limit_{100'000'000};
};

}  // namespace plexus::emulator
