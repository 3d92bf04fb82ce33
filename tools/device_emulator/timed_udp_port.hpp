// The emulator's UDP link with a jittery line and a device-grade time responder
// (docs/bridges.md, "Device time"; README.md, "Device time and jitter").
//
// A real device stamps a time request in its receive interrupt and its response as it
// leaves; the emulator's loop ticks once a step, which would add up to a step of one-sided
// delay to every exchange. So with this port two threads own the socket:
//   - the receiver takes each datagram as it arrives, holds it for its random delay
//     (0 .. jitter, first in first out, as a line that never reorders), then answers a time
//     request at once (t2 and t3 from the device clock) or hands the datagram to the loop;
//   - the sender holds each outgoing datagram (the loop's frames, the time responses) for
//     its random delay, again in order, and then sends it.
// The loop reads through poll() and writes through queue(), as with EmulatorLink. Fixed
// rings, allocated here; a full ring drops the datagram (counted). No pacing: a UDP device
// is not a serial line.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "device_clock_model.hpp"
#include "plexus/link/frame.hpp"

namespace plexus::emulator {

struct TimedPortCounters {
  uint64_t time_requests = 0;  ///< answered
  uint64_t datagrams_in = 0;   ///< handed to the loop
  uint64_t datagrams_out = 0;  ///< sent
  uint64_t ring_drops = 0;     ///< datagrams that found a ring full
  uint64_t send_errors = 0;
};

class TimedUdpPort {
 public:
  /// `fd`: the connected UDP socket (EmulatorLink's); `jitter_s` >= 0; `seed` seeds the delays.
  TimedUdpPort(int fd, DeviceClockModel clock, double jitter_s, uint64_t seed);
  ~TimedUdpPort();
  TimedUdpPort(const TimedUdpPort&) = delete;
  TimedUdpPort& operator=(const TimedUdpPort&) = delete;

  /// Hands each datagram whose delay is over to on_bytes(const uint8_t*, std::size_t).
  template <class OnBytes>
  void poll(OnBytes&& on_bytes) {
    Datagram d;
    while (pop_in(d)) on_bytes(d.bytes, d.len);
  }
  /// Queues one datagram to send after its delay; false if the ring is full (dropped).
  bool queue(const uint8_t* data, std::size_t n);
  TimedPortCounters counters() const;

 private:
  struct Datagram {
    int64_t due_ns = 0;  ///< CLOCK_REALTIME
    uint16_t len = 0;
    uint8_t bytes[link::kMaxEncodedFrame] = {};
  };
  struct Ring {
    std::vector<Datagram> slots;
    std::size_t head = 0, count = 0;
    int64_t last_due = 0;  // first in, first out: never due before the one ahead
  };
  void receive_loop();
  void send_loop();
  bool push(Ring& r, const uint8_t* data, std::size_t n, int64_t now_ns);  // under mu_
  int64_t delay_ns();                                                      // under mu_
  bool pop_in(Datagram& d);
  void answer(const link::Frame& request, int64_t now_ns);

  int fd_;
  DeviceClockModel clock_;
  double jitter_s_;
  std::mt19937_64 rng_;
  mutable std::mutex mu_;
  std::condition_variable send_cv_;
  Ring in_, out_;
  TimedPortCounters c_;
  link::FrameDecoder decoder_;  // receiver thread
  uint16_t response_seq_ = 0;   // receiver thread
  std::atomic<bool> stop_{false};
  std::thread receiver_, sender_;
};

}  // namespace plexus::emulator
