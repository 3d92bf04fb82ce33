// The device's end of the link: a pseudo-terminal (the bridge opens its slave through a
// symlink) or a connected UDP socket, read and written non-blocking from the emulator's loop.
//
// What the emulator sends goes through a TX ring (fixed size, allocated here) and leaves it
// at the line rate: 8N1 carries baud / 10 bytes per second, and each flush() writes at most
// what the line could have carried since the last write. On a pty the termios baud rate has
// no effect (the kernel moves bytes as fast as they are read), so this pacing is the only
// thing that makes the bridge see a serial line's timing. On UDP a datagram (one frame, or
// one burst of fault bytes) leaves whole when the line is free, and keeps the line busy for
// its length. Baud 0: everything queued is written at once.
//
// Nothing here allocates after construction; no error ends the emulator: it is counted
// (link_errors) and logged at most once a second.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "plexus/base/logging.hpp"
#include "plexus/link/udp_socket.hpp"

namespace plexus::emulator {

struct LinkOptions {
  enum class Kind { pty, udp };
  Kind kind = Kind::pty;
  std::string pty_path;           ///< pty: the symlink the bridge opens
  link::UdpEndpoint bind, peer;   ///< udp
  long baud = 1000000;            ///< 0: unpaced
  int64_t period_ns = 1'000'000;  ///< the loop's period: the most idle line time a flush may use
  std::size_t ring_bytes = 64 * 1024;
};

struct LinkCounters {
  uint64_t frames_sent = 0;  ///< frames written whole
  uint64_t bytes_sent = 0;   ///< every byte written (frames, fault bytes, resync delimiters)
  uint64_t bytes_received = 0;
  uint64_t frames_dropped_tx = 0;  ///< frames that found the TX ring full
  uint64_t bytes_dropped_tx = 0;   ///< fault bytes that found the TX ring full
  uint64_t write_drops = 0;        ///< frames the device would not take (EAGAIN, ENOBUFS): dropped
  uint64_t link_errors = 0;        ///< any other read or write error, and failed reopens
  uint64_t reopens = 0;            ///< link closed and opened again (unplug faults)
};

class EmulatorLink {
 public:
  explicit EmulatorLink(LinkOptions options);
  ~EmulatorLink();
  EmulatorLink(const EmulatorLink&) = delete;
  EmulatorLink& operator=(const EmulatorLink&) = delete;

  /// Opens the link; false with `error` set to one line naming the option and the cause.
  /// A pty gets its symlink (replaced atomically if it exists; an existing non-link there
  /// is refused).
  bool open(std::string& error);
  /// Closes it (a pty: master and slave, and removes the symlink); drops what is queued.
  void close();
  /// Opens again after close(); false (counted, logged at most once a second) on failure.
  bool reopen();
  bool is_open() const { return fd_ >= 0; }
  /// The pty master or the UDP socket (-1 while closed).
  int fd() const { return fd_; }
  /// "pty /tmp/x/tty -> /dev/pts/7", "udp 127.0.0.1:47002 -> 127.0.0.1:47001".
  std::string describe() const;

  /// Reads what has arrived (until EAGAIN, at most a bounded number of reads) and hands
  /// each piece to on_bytes(const uint8_t*, std::size_t).
  template <class OnBytes>
  void poll(OnBytes&& on_bytes) {
    for (int i = 0; i < kMaxReadsPerPoll; ++i) {
      const std::size_t n = read_some();
      if (n == 0) return;
      on_bytes(static_cast<const uint8_t*>(rx_), n);
    }
  }

  /// Queues a frame (is_frame) or raw bytes (one datagram on UDP). False if the ring has no
  /// room: the frame is dropped and counted (frames_dropped_tx).
  bool queue(const uint8_t* data, std::size_t n, bool is_frame);
  /// Whether `n` more bytes (one chunk) fit in the ring now.
  bool room_for(std::size_t n) const;
  /// Writes what the line rate allows by `now_ns` (CLOCK_MONOTONIC).
  void flush(int64_t now_ns);

  const LinkCounters& counters() const { return c_; }

 private:
  static constexpr int kMaxReadsPerPoll = 64;
  static constexpr std::size_t kMaxChunks = 4096;
  struct Chunk {
    uint32_t len = 0;
    uint32_t off = 0;  ///< bytes of it written (pty)
    bool frame = false;
  };

  bool open_pty(std::string& error);
  bool open_udp(std::string& error);
  std::size_t read_some();
  /// Writes up to n bytes of the head chunk from offset `off`; returns write()'s result.
  long write_head(std::size_t off, std::size_t n);
  void pop_head(bool written);
  void drop_all_queued();
  void count_error(const char* what, int err);
  bool line_free(int64_t now_ns, std::size_t& allowed);

  LinkOptions opt_;
  int fd_ = -1;           // pty master or the UDP socket
  int slave_fd_ = -1;     // pty: held open so the pty persists while no bridge has it open
  std::string tmp_link_;  // pty: symlink written here, then renamed over pty_path
  char slave_name_[128] = {};

  std::vector<uint8_t> ring_;
  std::size_t ring_head_ = 0, ring_used_ = 0;
  std::vector<Chunk> chunks_;
  std::size_t chunk_head_ = 0, chunk_count_ = 0;
  bool need_delimiter_ = false;  // a frame was cut short: lead the next bytes with 0x00
  double line_free_ns_ = 0.0;    // when the line has carried everything written so far
  double byte_ns_ = 0.0;         // 10 bits per byte (8N1)

  uint8_t rx_[4096] = {};
  LinkCounters c_;
  RateLimiter log_limit_;
};

}  // namespace plexus::emulator
