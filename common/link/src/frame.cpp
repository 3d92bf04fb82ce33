// Frame encoding and the streaming decoder. Everything works in fixed buffers (the decoder's
// own, or the caller's): the decoder runs on the bridge's receive path, byte by byte.
#include "plexus/link/frame.hpp"

#include <cstring>

#include "plexus/link/crc16.hpp"

namespace plexus::link {

std::size_t encode_frame(uint8_t id, uint16_t seq, const uint8_t* payload, std::size_t n, uint8_t* out) {
  if (n > kMaxPayload) return 0;
  uint8_t raw[kMaxRawFrame];
  raw[0] = kProtocolVersion;
  raw[1] = id;
  put_u16_le(raw + 2, seq);
  if (n > 0) std::memcpy(raw + kHeaderSize, payload, n);  // payload may be null when n == 0
  const std::size_t body = kHeaderSize + n;
  put_u16_le(raw + body, crc16(raw, body));
  const std::size_t len = cobs_encode(raw, body + kCrcSize, out);
  out[len] = 0;
  return len + 1;
}

bool FrameDecoder::push(uint8_t b) {
  if (discarding_) {  // the rest of an oversize frame, up to and including its delimiter
    ++counters_.bytes_discarded;
    if (b == 0) discarding_ = false;
    return false;
  }
  if (b != 0) {
    if (len_ < kMaxEncodedFrame - 1) {
      buf_[len_++] = b;
      return false;
    }
    // No valid frame is this long: drop what we have and skip to the next delimiter rather
    // than hunt for a frame start inside a block that has lost its boundaries.
    ++counters_.oversize;
    ++counters_.resyncs;
    counters_.bytes_discarded += len_ + 1;
    len_ = 0;
    discarding_ = true;
    return false;
  }
  if (len_ == 0) {
    // An empty block (a sender's leading flush 0x00, or two delimiters in a row): not an
    // error, but its byte is in no frame, so it is counted as discarded to keep every byte
    // accounted for.
    ++counters_.bytes_discarded;
    return false;
  }
  const bool ok = finish();
  len_ = 0;
  return ok;
}

// The block in buf_[0, len_) has just been ended by a delimiter.
bool FrameDecoder::finish() {
  auto drop = [this](uint64_t& why) {
    ++why;
    ++counters_.resyncs;
    counters_.bytes_discarded += len_ + 1;  // the block and its delimiter
    return false;
  };
  std::size_t n = 0;
  if (!cobs_decode(buf_, len_, raw_, n)) return drop(counters_.cobs_errors);
  if (n < kHeaderSize + kCrcSize) return drop(counters_.short_frames);
  const std::size_t payload = n - kHeaderSize - kCrcSize;
  // Unreachable while kMaxEncodedFrame bounds the block (a block decodes to fewer bytes than
  // it has), kept so that the payload copy below can never overrun whatever the constants.
  if (payload > kMaxPayload) return drop(counters_.oversize);
  if (crc16(raw_, n - kCrcSize) != get_u16_le(raw_ + n - kCrcSize)) return drop(counters_.crc_errors);
  // Checked after the CRC: a corrupt frame is a CRC error whatever its first byte says.
  if (raw_[0] != kProtocolVersion) return drop(counters_.version_errors);

  frame_.version = raw_[0];
  frame_.id = raw_[1];
  frame_.seq = get_u16_le(raw_ + 2);
  frame_.payload_size = payload;
  std::memcpy(frame_.payload, raw_ + kHeaderSize, payload);
  // Nothing of an earlier, longer frame stays visible past payload_size.
  std::memset(frame_.payload + payload, 0, kMaxPayload - payload);
  ++counters_.frames;
  return true;
}

void FrameDecoder::reset() {
  if (len_ > 0) {
    counters_.bytes_discarded += len_;
    ++counters_.resyncs;
  }
  len_ = 0;
  // The rest of an oversize frame was already counted; after a reconnect the next byte
  // starts a new frame.
  discarding_ = false;
}

void put_u16_le(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}

uint16_t get_u16_le(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }

// Through the bit pattern as an integer, then bytes by shifts: the same bytes on a
// little- and a big-endian host.
void put_f64_le(uint8_t* p, double v) {
  uint64_t bits = 0;
  static_assert(sizeof bits == sizeof v);
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(bits >> (8 * i));
}

double get_f64_le(const uint8_t* p) {
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<uint64_t>(p[i]) << (8 * i);
  double v = 0;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace plexus::link
