// libFuzzer target for the bridge's receive path (common/link): the COBS decoder and the
// frame decoder take bytes from a device we do not control, so no input may crash them,
// and what they hand on must be a frame the protocol allows.
//
// Input layout (the seed corpus in tests/fuzz/corpus/frame_decoder/ follows it):
//   byte 0          control: bits 0-2 = m, the number of chunk bytes; bit 3 = end the stream
//                   with reset() instead of a final 0x00; bit 4 = reset() after chunks
//                   whose chunk byte has bit 7 set (a reconnect mid-stream)
//   bytes 1..m      chunk bytes: feed() sizes (bits 0-6) + 1, used in turn, cycling
//   the rest        the byte stream (m == 0: fed in one call)
// (The seed cobs_full_group is there for the COBS check on the whole input: a full group
// followed by an empty one.)
//
// Checked: every frame handed on has our version and a payload within kMaxPayload, and
// encodes to a frame that decodes to itself; no counter ever decreases; every dropped
// block is one resync; every byte fed ends in a valid frame or in bytes_discarded. And on
// the whole input, cobs_decode followed by cobs_encode gives the input back.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fuzz_support.hpp"
#include "plexus/link/cobs.hpp"
#include "plexus/link/frame.hpp"

using namespace plexus::link;

namespace {

uint64_t errors(const DecoderCounters& c) {
  return c.crc_errors + c.cobs_errors + c.short_frames + c.version_errors + c.oversize;
}

void check_monotonic(const DecoderCounters& before, const DecoderCounters& now) {
  CHECK(now.frames >= before.frames);
  CHECK(now.crc_errors >= before.crc_errors);
  CHECK(now.cobs_errors >= before.cobs_errors);
  CHECK(now.short_frames >= before.short_frames);
  CHECK(now.version_errors >= before.version_errors);
  CHECK(now.oversize >= before.oversize);
  CHECK(now.resyncs >= before.resyncs);
  CHECK(now.bytes_discarded >= before.bytes_discarded);
}

bool same_frame(const Frame& a, const Frame& b) {
  return a.version == b.version && a.id == b.id && a.seq == b.seq && a.payload_size == b.payload_size &&
         std::memcmp(a.payload, b.payload, kMaxPayload) == 0;
}

// A frame the decoder handed on: valid, and the same after encoding and decoding it again.
// Returns its length on the link, which is the length of the block it came from (COBS
// has one encoding per input below 254 bytes).
std::size_t check_frame(const Frame& f) {
  CHECK(f.version == kProtocolVersion);
  CHECK(f.payload_size <= kMaxPayload);
  for (std::size_t i = f.payload_size; i < kMaxPayload; ++i) CHECK(f.payload[i] == 0);
  uint8_t wire[kMaxEncodedFrame];
  const std::size_t len = encode_frame(f.id, f.seq, f.payload, f.payload_size, wire);
  CHECK(len > 0 && len <= kMaxEncodedFrame);
  CHECK(wire[len - 1] == 0);
  CHECK(std::memchr(wire, 0, len - 1) == nullptr);
  FrameDecoder again;
  int n = 0;
  again.feed(wire, len, [&](const Frame& g) {
    ++n;
    CHECK(same_frame(f, g));
  });
  CHECK(n == 1);
  CHECK(again.counters().frames == 1 && again.counters().resyncs == 0 && again.counters().bytes_discarded == 0);
  return len;
}

void fuzz_cobs(const uint8_t* data, std::size_t size) {
  static uint8_t decoded[1 << 20], encoded[(1 << 20) + (1 << 13)], again[1 << 20];
  if (size > sizeof decoded) return;
  std::size_t n = 0;
  if (!cobs_decode(data, size, decoded, n)) return;
  CHECK(size > 0 && n < size);
  const std::size_t e = cobs_encode(decoded, n, encoded);
  CHECK(e <= cobs_max_encoded(n));
  CHECK(std::memchr(encoded, 0, e) == nullptr);
  std::size_t n2 = 0;
  CHECK(cobs_decode(encoded, e, again, n2));
  CHECK(n2 == n && std::memcmp(again, decoded, n) == 0);
  // The encoder is canonical; the one other form the decoder takes is a full group (0xFF)
  // ending the input followed by an empty group (0x01), which some encoders write.
  const bool same = e == size && std::memcmp(encoded, data, e) == 0;
  const bool trailing_empty_group = e + 1 == size && data[e] == 0x01 && std::memcmp(encoded, data, e) == 0;
  CHECK(same || trailing_empty_group);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  fuzz_cobs(data, size);
  if (size == 0) return 0;

  const uint8_t control = data[0];
  std::size_t m = control & 7;
  if (m > size - 1) m = size - 1;
  const uint8_t* chunks = data + 1;
  const uint8_t* stream = data + 1 + m;
  const std::size_t stream_size = size - 1 - m;
  const bool end_with_reset = control & 0x08;
  const bool resets = control & 0x10;

  FrameDecoder d;
  uint64_t delivered = 0, link_bytes = 0, fed = 0;
  bool did_reset = false;
  const auto on_frame = [&](const Frame& f) {
    ++delivered;
    link_bytes += check_frame(f);
  };
  const auto step = [&](const uint8_t* p, std::size_t n) {
    const DecoderCounters before = d.counters();
    d.feed(p, n, on_frame);
    fed += n;
    check_monotonic(before, d.counters());
    CHECK(d.counters().frames == delivered);
    // Before any reset, each dropped block counts one resync and one reason.
    if (!did_reset) CHECK(d.counters().resyncs == errors(d.counters()));
    CHECK(d.counters().resyncs >= errors(d.counters()));
  };
  const auto reset = [&] {
    const DecoderCounters before = d.counters();
    d.reset();
    did_reset = true;
    check_monotonic(before, d.counters());
    CHECK(d.counters().frames == before.frames);
  };

  std::size_t at = 0, k = 0;
  while (at < stream_size) {
    std::size_t n = stream_size - at;
    uint8_t c = 0;
    if (m > 0) {
      c = chunks[k++ % m];
      if (n > static_cast<std::size_t>(c & 0x7F) + 1) n = static_cast<std::size_t>(c & 0x7F) + 1;
    }
    step(stream + at, n);
    at += n;
    if (resets && (c & 0x80)) reset();
  }
  // End the stream so that every byte is settled.
  if (end_with_reset) {
    reset();
  } else {
    const uint8_t delimiter = 0;
    step(&delimiter, 1);
  }
  CHECK(link_bytes + d.counters().bytes_discarded == fed);
  return 0;
}
