// The bridge frame (docs/bridges.md "Framing"), the same on a serial line and in a UDP
// datagram:
//
//   raw frame:  version u8 | id u8 | seq u16 LE | payload (0..kMaxPayload bytes) | crc u16 LE
//   on the link: COBS(raw frame) 0x00
//
// The CRC (crc16.hpp) covers version, id, seq and payload. The payload's length is fixed by
// the id (protocol.hpp); this layer does not know the ids and accepts any length up to
// kMaxPayload. Nothing here allocates: the decoder works in a buffer of its own.
#pragma once

#include <cstddef>
#include <cstdint>

#include "plexus/link/cobs.hpp"

namespace plexus::link {

inline constexpr uint8_t kProtocolVersion = 1;
inline constexpr std::size_t kHeaderSize = 4;  ///< version, id, seq
inline constexpr std::size_t kCrcSize = 2;
inline constexpr std::size_t kMaxPayload = 1024;  ///< bytes: 128 little-endian f64 (a 16-joint arm's truth: 80)
inline constexpr std::size_t kMaxRawFrame = kHeaderSize + kMaxPayload + kCrcSize;
/// Longest frame on the link, delimiter included. A longer run of bytes without a 0x00 is
/// an oversize frame: dropped, and the decoder resyncs at the next delimiter.
inline constexpr std::size_t kMaxEncodedFrame = cobs_max_encoded(kMaxRawFrame) + 1;

/// One decoded frame.
struct Frame {
  uint8_t version = 0;
  uint8_t id = 0;
  uint16_t seq = 0;
  std::size_t payload_size = 0;
  uint8_t payload[kMaxPayload] = {};
};

/// Writes frame (id, seq, payload) as it goes on the link, delimiter included, into `out`
/// (room for kMaxEncodedFrame). Returns the bytes written, or 0 if n > kMaxPayload.
std::size_t encode_frame(uint8_t id, uint16_t seq, const uint8_t* payload, std::size_t n, uint8_t* out);

/// What the decoder saw, since construction. Every byte received ends up in exactly one
/// frame (valid or not) or in bytes_discarded.
struct DecoderCounters {
  uint64_t frames = 0;           ///< valid frames handed on
  uint64_t crc_errors = 0;       ///< CRC mismatch: dropped
  uint64_t cobs_errors = 0;      ///< malformed COBS block: dropped
  uint64_t short_frames = 0;     ///< shorter than header + CRC: dropped
  uint64_t version_errors = 0;   ///< CRC good, unknown protocol version: dropped
  uint64_t oversize = 0;         ///< no delimiter within kMaxEncodedFrame bytes: dropped
  uint64_t resyncs = 0;          ///< times the decoder dropped bytes and waited for the next delimiter
  uint64_t bytes_discarded = 0;  ///< bytes of dropped frames and of garbage
};

/// Splits a byte stream at 0x00 delimiters and checks each frame. Bytes may arrive in any
/// pieces; a frame split across feed() calls is reassembled. An empty block (two delimiters
/// in a row) is ignored: senders may lead every frame with a 0x00 to flush line noise.
class FrameDecoder {
 public:
  /// Feeds `n` bytes; calls on_frame(const Frame&) for each valid frame, in order.
  template <class OnFrame>
  void feed(const uint8_t* data, std::size_t n, OnFrame&& on_frame) {
    for (std::size_t i = 0; i < n; ++i)
      if (push(data[i])) on_frame(static_cast<const Frame&>(frame_));
  }

  /// Forgets a partial frame (after a reconnect): its bytes count as discarded.
  void reset();
  const DecoderCounters& counters() const { return counters_; }

 private:
  /// One byte; true when it completed a valid frame (then in frame_).
  bool push(uint8_t b);
  bool finish();

  uint8_t buf_[kMaxEncodedFrame] = {};
  uint8_t raw_[kMaxEncodedFrame] = {};
  std::size_t len_ = 0;
  bool discarding_ = false;  // after an oversize frame: until the next delimiter
  Frame frame_;
  DecoderCounters counters_;
};

/// Little-endian payload fields.
void put_f64_le(uint8_t* p, double v);
double get_f64_le(const uint8_t* p);
void put_u16_le(uint8_t* p, uint16_t v);
uint16_t get_u16_le(const uint8_t* p);

}  // namespace plexus::link
