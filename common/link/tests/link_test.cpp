// The bridge link layer (docs/bridges.md "Framing"): the CRC and COBS against published
// vectors, the frame decoder against the faults a serial line or a network produces (noise,
// lost bytes, flipped bits, runaway senders), the message table, and the two transports on
// a pseudo-terminal and on loopback UDP.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "plexus/link/cobs.hpp"
#include "plexus/link/crc16.hpp"
#include "plexus/link/frame.hpp"
#include "plexus/link/protocol.hpp"
#include "plexus/link/serial_port.hpp"
#include "plexus/link/udp_socket.hpp"

namespace plexus::link {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes bytes_of(const std::string& s) { return Bytes(s.begin(), s.end()); }

// --- CRC-16/CCITT-FALSE --------------------------------------------------------------

// Bit by bit, straight from the definition: the table-driven crc16 must agree with it.
uint16_t crc16_bitwise(const Bytes& d) {
  uint16_t c = 0xFFFF;
  for (uint8_t b : d) {
    c ^= static_cast<uint16_t>(b << 8);
    for (int i = 0; i < 8; ++i) c = static_cast<uint16_t>((c & 0x8000) ? (c << 1) ^ 0x1021 : c << 1);
  }
  return c;
}

TEST(Crc16, CheckValue) {
  const Bytes d = bytes_of("123456789");
  EXPECT_EQ(crc16(d.data(), d.size()), 0x29B1);
}

TEST(Crc16, EmptyInputIsTheInitialValue) { EXPECT_EQ(crc16(nullptr, 0), 0xFFFF); }

TEST(Crc16, SingleByte) {
  const uint8_t a = 'A';
  EXPECT_EQ(crc16(&a, 1), 0xB915);
}

TEST(Crc16, ContinuesAcrossPieces) {
  const Bytes d = bytes_of("123456789");
  EXPECT_EQ(crc16(d.data() + 4, 5, crc16(d.data(), 4)), 0x29B1);
}

TEST(Crc16, MatchesTheBitwiseDefinition) {
  std::mt19937 rng(1);
  for (std::size_t n = 0; n < 200; ++n) {
    Bytes d(n);
    for (auto& b : d) b = static_cast<uint8_t>(rng());
    EXPECT_EQ(crc16(d.data(), d.size()), crc16_bitwise(d)) << "length " << n;
  }
}

// --- COBS ------------------------------------------------------------------------------

Bytes encode(const Bytes& in) {
  Bytes out(cobs_max_encoded(in.size()));
  out.resize(cobs_encode(in.data(), in.size(), out.data()));
  return out;
}

bool decode(const Bytes& in, Bytes& out) {
  out.assign(in.size(), 0xEE);
  std::size_t n = 0;
  const bool ok = cobs_decode(in.data(), in.size(), out.data(), n);
  if (ok) out.resize(n);
  return ok;
}

Bytes iota(uint8_t first, std::size_t n) {
  Bytes b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<uint8_t>(first + i);
  return b;
}

Bytes cat(std::initializer_list<Bytes> parts) {
  Bytes r;
  for (const auto& p : parts) r.insert(r.end(), p.begin(), p.end());
  return r;
}

// The eleven examples of the Wikipedia article "Consistent Overhead Byte Stuffing", without
// the trailing delimiter (which cobs_encode does not write).
struct CobsVector {
  const char* name;
  Bytes decoded, encoded;
};

std::vector<CobsVector> cobs_vectors() {
  return {
      {"1: 00", {0x00}, {0x01, 0x01}},
      {"2: 00 00", {0x00, 0x00}, {0x01, 0x01, 0x01}},
      {"3: 00 11 00", {0x00, 0x11, 0x00}, {0x01, 0x02, 0x11, 0x01}},
      {"4: 11 22 00 33", {0x11, 0x22, 0x00, 0x33}, {0x03, 0x11, 0x22, 0x02, 0x33}},
      {"5: 11 22 33 44", {0x11, 0x22, 0x33, 0x44}, {0x05, 0x11, 0x22, 0x33, 0x44}},
      {"6: 11 00 00 00", {0x11, 0x00, 0x00, 0x00}, {0x02, 0x11, 0x01, 0x01, 0x01}},
      // 254 non-zero bytes: one full group, no empty group after it.
      {"7: 01..FE", iota(0x01, 254), cat({{0xFF}, iota(0x01, 254)})},
      {"8: 00 01..FE", cat({{0x00}, iota(0x01, 254)}), cat({{0x01, 0xFF}, iota(0x01, 254)})},
      {"9: 01..FF", iota(0x01, 255), cat({{0xFF}, iota(0x01, 254), {0x02, 0xFF}})},
      {"10: 02..FF 00", cat({iota(0x02, 254), {0x00}}), cat({{0xFF}, iota(0x02, 254), {0x01, 0x01}})},
      {"11: 03..FF 00 01", cat({iota(0x03, 253), {0x00, 0x01}}), cat({{0xFE}, iota(0x03, 253), {0x02, 0x01}})},
  };
}

TEST(Cobs, WikipediaVectorsEncode) {
  for (const auto& v : cobs_vectors()) EXPECT_EQ(encode(v.decoded), v.encoded) << v.name;
}

TEST(Cobs, WikipediaVectorsDecode) {
  for (const auto& v : cobs_vectors()) {
    Bytes out;
    ASSERT_TRUE(decode(v.encoded, out)) << v.name;
    EXPECT_EQ(out, v.decoded) << v.name;
  }
}

TEST(Cobs, EmptyInputEncodesToOneCodeByte) {
  EXPECT_EQ(encode({}), Bytes{0x01});
  Bytes out;
  ASSERT_TRUE(decode({0x01}, out));
  EXPECT_TRUE(out.empty());
}

TEST(Cobs, RoundTripsRandomDataOfEveryLength) {
  std::mt19937 rng(2);
  // Zero density from none to all: long runs (full 0xFF groups) and dense zeros both occur.
  for (int zero_percent : {0, 1, 10, 50, 100}) {
    for (std::size_t n = 0; n <= 300; ++n) {
      Bytes d(n);
      for (auto& b : d) b = (static_cast<int>(rng() % 100) < zero_percent) ? 0 : static_cast<uint8_t>(1 + rng() % 255);
      const Bytes e = encode(d);
      ASSERT_LE(e.size(), cobs_max_encoded(n));
      ASSERT_EQ(std::count(e.begin(), e.end(), 0), 0) << "length " << n;
      Bytes back;
      ASSERT_TRUE(decode(e, back)) << "length " << n;
      ASSERT_EQ(back, d) << "length " << n << ", " << zero_percent << "% zeros";
    }
  }
}

TEST(Cobs, MalformedBlocksAreRejected) {
  const std::vector<std::pair<const char*, Bytes>> bad = {
      {"empty block", {}},
      {"a zero code byte", {0x00}},
      {"a zero data byte", {0x03, 0x11, 0x00}},
      {"a zero after a group", {0x02, 0x11, 0x00}},
      {"a code past the end", {0x05, 0x11, 0x22}},
      {"a second code past the end", {0x02, 0x11, 0x03, 0x22}},
      {"a full group cut short", cat({{0xFF}, iota(0x01, 200)})},
  };
  for (const auto& [why, block] : bad) {
    Bytes out;
    EXPECT_FALSE(decode(block, out)) << why;
  }
}

// --- frames ---------------------------------------------------------------------------

struct Sent {
  uint8_t id;
  uint16_t seq;
  Bytes payload;
};

Bytes encode_frame(const Sent& s) {
  Bytes out(kMaxEncodedFrame);
  out.resize(link::encode_frame(s.id, s.seq, s.payload.data(), s.payload.size(), out.data()));
  return out;
}

// A frame as the decoder handed it on, copied out of the callback.
Sent received(const Frame& f) {
  EXPECT_EQ(f.version, kProtocolVersion);
  return {f.id, f.seq, Bytes(f.payload, f.payload + f.payload_size)};
}

bool operator==(const Sent& a, const Sent& b) { return a.id == b.id && a.seq == b.seq && a.payload == b.payload; }

std::ostream& operator<<(std::ostream& os, const Sent& s) {
  return os << "frame id " << int(s.id) << " seq " << s.seq << " payload " << s.payload.size() << " bytes";
}

struct Collect {
  FrameDecoder decoder;
  std::vector<Sent> frames;
  void feed(const Bytes& b) { feed(b.data(), b.size()); }
  void feed(const uint8_t* p, std::size_t n) {
    decoder.feed(p, n, [this](const Frame& f) { frames.push_back(received(f)); });
  }
  const DecoderCounters& c() const { return decoder.counters(); }
};

Sent random_frame(std::mt19937& rng) {
  Sent s{static_cast<uint8_t>(rng()), static_cast<uint16_t>(rng()), Bytes(rng() % (kMaxPayload + 1))};
  for (auto& b : s.payload) b = (rng() % 4 == 0) ? 0 : static_cast<uint8_t>(rng());
  return s;
}

// Bytes in valid frames (delimiters included) plus bytes_discarded: every byte fed once a
// stream has ended with a delimiter.
uint64_t accounted(const Collect& c) {
  uint64_t n = c.c().bytes_discarded;
  for (const auto& f : c.frames) n += encode_frame(f).size();
  return n;
}

uint64_t errors(const DecoderCounters& c) {
  return c.crc_errors + c.cobs_errors + c.short_frames + c.version_errors + c.oversize;
}

TEST(Frame, StopFrameBytes) {
  // raw 01 8F 00 00 | CRC 0xE51F little-endian; COBS; delimiter.
  EXPECT_EQ(encode_frame(Sent{kStopId, 0, {}}), (Bytes{0x03, 0x01, 0x8F, 0x01, 0x03, 0x1F, 0xE5, 0x00}));
  uint8_t out[kMaxEncodedFrame];
  EXPECT_EQ(link::encode_frame(kStopId, 0, nullptr, 0, out), 8u);  // no payload pointer needed
}

TEST(Frame, UnicycleCommandBytes) {
  // id 0x80, seq 1, v = 1.0, omega = -0.5.
  Bytes payload(16);
  put_f64_le(payload.data(), 1.0);
  put_f64_le(payload.data() + 8, -0.5);
  const Bytes expected = {0x04, 0x01, 0x80, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x03, 0xF0,
                          0x3F, 0x01, 0x01, 0x01, 0x01, 0x01, 0x05, 0xE0, 0xBF, 0x96, 0xB0, 0x00};
  EXPECT_EQ(encode_frame(Sent{0x80, 1, payload}), expected);
}

// docs/bridges.md's worked frames of the skid-steer's and the arm's commands (checked there
// against an independent encoding: Python's struct, a bitwise CRC and COBS).
TEST(Frame, TrackCommandBytes) {
  // id 0x82, seq 7, v_l = 0.5, v_r = -0.25.
  Bytes payload(16);
  const double values[] = {0.5, -0.25};
  ASSERT_EQ(find_layout(0x82)->encode(values, payload.data()), 16u);
  const Bytes expected = {0x04, 0x01, 0x82, 0x07, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x03, 0xE0,
                          0x3F, 0x01, 0x01, 0x01, 0x01, 0x01, 0x05, 0xD0, 0xBF, 0x6E, 0x8D, 0x00};
  EXPECT_EQ(encode_frame(Sent{0x82, 7, payload}), expected);
}

TEST(Frame, JointCommandOfATwoJointArmBytes) {
  // id 0x83 sized for 2 joints (u1, u2), seq 2, u1 = 1.5, u2 = -2.0.
  const MessageLayout l = for_joints(*find_layout(0x83), 2);
  ASSERT_EQ(l.payload_size(), 16u);
  Bytes payload(16);
  const double values[] = {1.5, -2.0};
  l.encode(values, payload.data());
  const Bytes expected = {0x04, 0x01, 0x83, 0x02, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x03, 0xF8,
                          0x3F, 0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x04, 0xC0, 0x65, 0x17, 0x00};
  EXPECT_EQ(encode_frame(Sent{0x83, 2, payload}), expected);
}

TEST(Frame, TooLongPayloadIsNotEncoded) {
  uint8_t payload[kMaxPayload + 1] = {};
  uint8_t out[kMaxEncodedFrame + 8];
  EXPECT_EQ(link::encode_frame(0x10, 0, payload, kMaxPayload + 1, out), 0u);
  EXPECT_GT(link::encode_frame(0x10, 0, payload, kMaxPayload, out), 0u);
}

// The longest frame on the link is exactly kMaxEncodedFrame bytes, and the decoder takes it.
TEST(Frame, LongestFrameFitsTheDecoder) {
  Sent s{0x22, 0, Bytes(kMaxPayload, 0xA5)};
  Bytes e;
  for (s.seq = 1;; ++s.seq) {  // a seq whose CRC has no zero byte: no COBS group shortens it
    e = encode_frame(s);
    if (e.size() == kMaxEncodedFrame) break;
    ASSERT_LT(s.seq, 1000);
  }
  Collect c;
  c.feed(e);
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  EXPECT_EQ(c.c().oversize, 0u);
}

TEST(Frame, RoundTripByteByByte) {
  std::mt19937 rng(3);
  Collect c;
  std::vector<Sent> sent;
  uint64_t fed = 0;
  for (int i = 0; i < 500; ++i) {
    sent.push_back(random_frame(rng));
    const Bytes e = encode_frame(sent.back());
    ASSERT_LE(e.size(), kMaxEncodedFrame);
    for (uint8_t b : e) c.feed(&b, 1);
    fed += e.size();
  }
  ASSERT_EQ(c.frames.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(c.frames[i], sent[i]) << "frame " << i;
  EXPECT_EQ(c.c().frames, sent.size());
  EXPECT_EQ(errors(c.c()), 0u);
  EXPECT_EQ(c.c().resyncs, 0u);
  EXPECT_EQ(c.c().bytes_discarded, 0u);
  EXPECT_EQ(accounted(c), fed);
}

TEST(Frame, RoundTripInRandomChunks) {
  std::mt19937 rng(4);
  std::vector<Sent> sent;
  Bytes stream;
  for (int i = 0; i < 500; ++i) {
    sent.push_back(random_frame(rng));
    const Bytes e = encode_frame(sent.back());
    stream.insert(stream.end(), e.begin(), e.end());
  }
  Collect c;
  for (std::size_t at = 0; at < stream.size();) {
    const std::size_t n = std::min<std::size_t>(stream.size() - at, rng() % 300);
    c.feed(stream.data() + at, n);
    at += n;
  }
  ASSERT_EQ(c.frames.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(c.frames[i], sent[i]) << "frame " << i;
  EXPECT_EQ(errors(c.c()), 0u);
  EXPECT_EQ(accounted(c), stream.size());
}

TEST(Frame, EmptyBlocksAreNotErrors) {
  Collect c;
  const Sent s{0x10, 7, Bytes(32, 0x01)};
  c.feed({0x00, 0x00});
  c.feed(encode_frame(s));
  c.feed({0x00});
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(errors(c.c()), 0u);
  EXPECT_EQ(c.c().resyncs, 0u);
  // The three lone delimiters are in no frame: they are the only discarded bytes.
  EXPECT_EQ(c.c().bytes_discarded, 3u);
}

// A frame the decoder may hand on after `s` was corrupted: `s` itself, or `s` cut short at
// a COBS group boundary (see BitFlipInACodeByteCanTruncateAFrame): same id and seq, a
// strictly shorter payload that begins like the sent one.
bool same_or_truncated(const Sent& got, const Sent& s) {
  if (got == s) return true;
  return got.id == s.id && got.seq == s.seq && got.payload.size() < s.payload.size() &&
         std::equal(got.payload.begin(), got.payload.end(), s.payload.begin());
}

// One flipped bit anywhere in a frame (its delimiter included) never yields a frame with
// other content of the sent length. In a data byte it is a 1-bit error, which CRC-16
// always detects. A bit that turns a byte into 0x00 splits the block, and one in the
// delimiter merges two; each piece is then checked on its own, and a piece that ends at a
// group boundary is a truncated frame, which passes the CRC with odds of 2^-16. A flush
// 0x00 before the next frame makes that one survive even when the flip hit the delimiter.
TEST(Frame, AnySingleBitFlipIsDetected) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const Sent s = random_frame(rng);
    const Sent next{0x21, static_cast<uint16_t>(trial), Bytes(16, 0x42)};
    const Bytes e = encode_frame(s);
    for (std::size_t at = 0; at < e.size(); ++at) {
      for (int bit = 0; bit < 8; ++bit) {
        Bytes stream = e;
        stream[at] ^= static_cast<uint8_t>(1u << bit);
        stream.push_back(0x00);
        const Bytes n = encode_frame(next);
        stream.insert(stream.end(), n.begin(), n.end());
        Collect c;
        c.feed(stream);
        ASSERT_FALSE(c.frames.empty());
        EXPECT_EQ(c.frames.back(), next) << "byte " << at << " bit " << bit;
        for (std::size_t i = 0; i + 1 < c.frames.size(); ++i)
          EXPECT_TRUE(same_or_truncated(c.frames[i], s)) << "a corrupted frame passed: byte " << at << " bit " << bit;
        EXPECT_GE(errors(c.c()), 1u);
        EXPECT_EQ(accounted(c), stream.size());
      }
    }
  }
}

// The limit of the CRC behind COBS, found by flipping every bit of 20000 random frames
// (11.6 million flips, 2 such frames): the 0x04 code byte at offset 8 of this frame loses
// bit 2 and becomes a delimiter. The block before it ends at a group boundary, so it
// decodes, and its last two bytes happen to be the CRC of the rest. The decoder hands on
// id 0x11 seq 5509 with 1 payload byte instead of 96: the bridge must, and does, refuse a
// payload whose length is not its id's (docs/bridges.md "wrong length for its id").
TEST(Frame, BitFlipInACodeByteCanTruncateAFrame) {
  Bytes wire = {0x08, 0x01, 0x11, 0x85, 0x15, 0x5D, 0x3A, 0x71, 0x04, 0x86, 0x79, 0xE6, 0x06, 0xCE, 0x67,
                0xC6, 0xE3, 0x45, 0x05, 0x96, 0xAB, 0xE7, 0x4F, 0x01, 0x0C, 0x3C, 0x24, 0x0F, 0x7A, 0x36,
                0x9D, 0x88, 0xAA, 0x5A, 0x4F, 0x16, 0x07, 0x54, 0x38, 0xF1, 0xF1, 0xF5, 0x54, 0x01, 0x05,
                0x66, 0x78, 0x94, 0x36, 0x04, 0xB1, 0x08, 0xB0, 0x05, 0xA3, 0x77, 0x6F, 0x9A, 0x0B, 0xE4,
                0x8F, 0x3C, 0x7E, 0x3C, 0xE2, 0xE7, 0xA8, 0x4C, 0xCB, 0x0A, 0xD6, 0xD0, 0xCB, 0x8B, 0xBB,
                0x45, 0x6F, 0xBA, 0x5E, 0x02, 0x85, 0x06, 0x48, 0x4B, 0x55, 0xE7, 0xD3, 0x02, 0xF3, 0x0E,
                0x35, 0xE4, 0xCF, 0x20, 0x0C, 0x39, 0xFA, 0x45, 0x80, 0x63, 0xC2, 0xEA, 0xC3, 0x00};
  Collect intact;
  intact.feed(wire);
  ASSERT_EQ(intact.frames.size(), 1u);
  const Sent sent = intact.frames[0];
  EXPECT_EQ(sent.payload.size(), 96u);

  wire[8] ^= 0x04;
  Collect c;
  c.feed(wire);
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0].id, 0x11);
  EXPECT_EQ(c.frames[0].seq, 5509);
  EXPECT_EQ(c.frames[0].payload.size(), 1u);
  EXPECT_TRUE(same_or_truncated(c.frames[0], sent));
  EXPECT_NE(c.frames[0].payload.size(), find_layout(uint8_t{0x11})->payload_size());
  EXPECT_EQ(errors(c.c()), 1u);  // the rest of the frame
}

TEST(Frame, GarbageThenValidFrameIsRecovered) {
  std::mt19937 rng(6);
  Bytes garbage(1000);
  for (auto& b : garbage) b = static_cast<uint8_t>(rng());  // zeros included: many short blocks
  const Sent s{0x20, 99, Bytes(48, 0x07)};
  Collect c;
  c.feed(garbage);
  c.feed({0x00});
  c.feed(encode_frame(s));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  EXPECT_GE(c.c().resyncs, 1u);
  EXPECT_EQ(c.c().resyncs, errors(c.c()));  // one resync per dropped block
  EXPECT_EQ(c.c().bytes_discarded, garbage.size() + 1);
}

TEST(Frame, NoiseWithoutZerosIsOneBadBlock) {
  const Sent s{0x10, 1, Bytes(32, 0x33)};
  Collect c;
  c.feed(bytes_of("hello, noise\r\n"));  // a boot message on the line, say
  c.feed({0x00});
  c.feed(encode_frame(s));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.c().resyncs, 1u);
  EXPECT_EQ(c.c().bytes_discarded, 15u);
}

TEST(Frame, OversizeRunThenValidFrame) {
  const Sent s{0x11, 5, Bytes(24, 0x09)};
  Collect c;
  const std::size_t run = kMaxEncodedFrame + 500;
  c.feed(Bytes(run, 0x55));
  EXPECT_EQ(c.c().oversize, 1u);  // once per run, not per byte
  EXPECT_EQ(c.c().resyncs, 1u);
  c.feed({0x00});
  c.feed(encode_frame(s));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  EXPECT_EQ(c.c().oversize, 1u);
  EXPECT_EQ(c.c().resyncs, 1u);
  EXPECT_EQ(c.c().bytes_discarded, run + 1);
}

// Without a delimiter after the run, the decoder cannot tell where the next frame starts:
// that frame is lost with the run, and the one after it arrives.
TEST(Frame, OversizeRunSwallowsTheFrameItRunsInto) {
  const Sent a{0x11, 1, Bytes(24, 0x09)}, b{0x11, 2, Bytes(24, 0x0A)};
  const Bytes ea = encode_frame(a);
  Collect c;
  const std::size_t run = kMaxEncodedFrame + 164;
  c.feed(Bytes(run, 0x55));
  c.feed(ea);
  c.feed(encode_frame(b));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], b);
  EXPECT_EQ(c.c().oversize, 1u);
  EXPECT_EQ(c.c().bytes_discarded, run + ea.size());
}

TEST(Frame, OversizeBoundary) {
  {
    Collect c;  // kMaxEncodedFrame - 1 bytes and a delimiter: could be a frame, checked as one
    c.feed(Bytes(kMaxEncodedFrame - 1, 0x55));
    c.feed({0x00});
    EXPECT_EQ(c.c().oversize, 0u);
    EXPECT_EQ(errors(c.c()), 1u);
    EXPECT_EQ(c.c().bytes_discarded, kMaxEncodedFrame);
  }
  {
    Collect c;  // kMaxEncodedFrame bytes: oversize
    c.feed(Bytes(kMaxEncodedFrame, 0x55));
    c.feed({0x00});
    EXPECT_EQ(c.c().oversize, 1u);
    EXPECT_EQ(errors(c.c()), 1u);
    EXPECT_EQ(c.c().bytes_discarded, kMaxEncodedFrame + 1);
  }
}

TEST(Frame, TruncatedFrameIsDroppedAndTheNextRecovered) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Sent a = random_frame(rng), b = random_frame(rng);
    Bytes ea = encode_frame(a);
    // Lose 1..8 bytes somewhere before the delimiter (a UART overrun).
    // At least one byte stays: a frame reduced to its delimiter is an empty block, not an error.
    const std::size_t lost = std::min<std::size_t>(1 + rng() % 8, ea.size() - 2);
    const std::size_t at = rng() % (ea.size() - lost);
    ea.erase(ea.begin() + static_cast<long>(at), ea.begin() + static_cast<long>(at + lost));
    Collect c;
    c.feed(ea);
    c.feed(encode_frame(b));
    ASSERT_FALSE(c.frames.empty());
    EXPECT_EQ(c.frames.back(), b) << "trial " << trial;
    EXPECT_EQ(c.frames.size(), 1u) << "trial " << trial;
    EXPECT_EQ(errors(c.c()), 1u) << "trial " << trial;
    EXPECT_EQ(c.c().resyncs, 1u);
    EXPECT_EQ(c.c().bytes_discarded, ea.size());
  }
}

// A raw frame with a good CRC, built by hand: the version and length checks come after it.
Bytes link_bytes(Bytes raw) {
  const uint16_t crc = crc16(raw.data(), raw.size());
  raw.push_back(static_cast<uint8_t>(crc));
  raw.push_back(static_cast<uint8_t>(crc >> 8));
  Bytes out(cobs_max_encoded(raw.size()) + 1);
  out.resize(cobs_encode(raw.data(), raw.size(), out.data()));
  out.push_back(0x00);
  return out;
}

TEST(Frame, WrongVersionIsCounted) {
  Collect c;
  c.feed(link_bytes({2, 0x10, 0x00, 0x00, 1, 2, 3, 4, 5, 6, 7, 8}));
  c.feed(link_bytes({kProtocolVersion, 0x10, 0x00, 0x00, 1, 2, 3, 4, 5, 6, 7, 8}));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.c().version_errors, 1u);
  EXPECT_EQ(c.c().crc_errors, 0u);
  EXPECT_EQ(c.c().resyncs, 1u);
}

TEST(Frame, ShortFramesAreCounted) {
  Collect c;
  c.feed(link_bytes({kProtocolVersion, 0x10, 0x00}));  // no room for a seq: 5 bytes
  c.feed({0x02, 0x01, 0x00});                          // a one-byte block that decodes fine
  EXPECT_EQ(c.c().short_frames, 2u);
  EXPECT_EQ(c.c().resyncs, 2u);
  EXPECT_TRUE(c.frames.empty());
}

TEST(Frame, CorruptCobsIsCounted) {
  Collect c;
  c.feed({0x09, 0x01, 0x02, 0x00});  // the code byte points past the block
  EXPECT_EQ(c.c().cobs_errors, 1u);
  EXPECT_EQ(c.c().bytes_discarded, 4u);
}

TEST(Frame, ResetDropsAPartialFrame) {
  const Sent s{0x21, 3, Bytes(16, 0x11)};
  const Bytes e = encode_frame(s);
  Collect c;
  c.decoder.reset();  // nothing pending: nothing counted
  EXPECT_EQ(c.c().resyncs, 0u);
  c.feed(e.data(), 10);
  c.decoder.reset();
  EXPECT_EQ(c.c().resyncs, 1u);
  EXPECT_EQ(c.c().bytes_discarded, 10u);
  c.feed(e);  // a whole frame right after: no leading delimiter needed
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  // In the middle of an oversize run: the run was counted; the next byte starts afresh.
  c.feed(Bytes(kMaxEncodedFrame + 64, 0x55));
  c.decoder.reset();
  c.feed(e);
  EXPECT_EQ(c.frames.size(), 2u);
  EXPECT_EQ(c.c().oversize, 1u);
  EXPECT_EQ(c.c().resyncs, 2u);
  EXPECT_EQ(c.c().bytes_discarded, 10u + kMaxEncodedFrame + 64);
}

TEST(Frame, ShorterFrameLeavesNoStalePayload) {
  FrameDecoder d;
  Frame last;
  const auto keep = [&](const Frame& f) { last = f; };
  const Bytes big = encode_frame(Sent{0x22, 0, Bytes(48, 0x77)});
  const Bytes small = encode_frame(Sent{0x21, 1, Bytes(16, 0x01)});
  d.feed(big.data(), big.size(), keep);
  d.feed(small.data(), small.size(), keep);
  EXPECT_EQ(last.payload_size, 16u);
  for (std::size_t i = 16; i < kMaxPayload; ++i) ASSERT_EQ(last.payload[i], 0) << i;
}

// --- payload fields ---------------------------------------------------------------------

TEST(Payload, F64LittleEndianBytes) {
  uint8_t p[8];
  put_f64_le(p, 1.0);
  EXPECT_EQ(Bytes(p, p + 8), (Bytes{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F}));
  put_f64_le(p, -2.5);
  EXPECT_EQ(Bytes(p, p + 8), (Bytes{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0xC0}));
  const uint8_t pi[8] = {0x18, 0x2D, 0x44, 0x54, 0xFB, 0x21, 0x09, 0x40};
  EXPECT_EQ(get_f64_le(pi), 3.141592653589793);
}

TEST(Payload, F64RoundTripsEveryBitPattern) {
  const double values[] = {0.0,
                           -0.0,
                           1e-310 /* subnormal */,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::infinity(),
                           -123.456};
  uint8_t p[8];
  for (double v : values) {
    put_f64_le(p, v);
    const double back = get_f64_le(p);
    EXPECT_EQ(std::memcmp(&back, &v, 8), 0) << v;
  }
  put_f64_le(p, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(get_f64_le(p)));
}

TEST(Payload, U16LittleEndian) {
  uint8_t p[2];
  put_u16_le(p, 0x1234);
  EXPECT_EQ(p[0], 0x34);
  EXPECT_EQ(p[1], 0x12);
  EXPECT_EQ(get_u16_le(p), 0x1234);
}

// --- message table ----------------------------------------------------------------------

TEST(Protocol, IdsAreUniqueAndPayloadsFit) {
  std::set<uint8_t> ids;
  for (const auto& l : message_layouts()) {
    EXPECT_TRUE(ids.insert(l.id).second) << "duplicate id " << int(l.id);
    EXPECT_LE(l.payload_size(), kMaxPayload) << "id " << int(l.id);
    EXPECT_EQ(find_layout(l.id), &l);
  }
  EXPECT_EQ(find_layout(uint8_t{0x00}), nullptr);
  EXPECT_EQ(find_layout(uint8_t{0xFF}), nullptr);
}

TEST(Protocol, FindByTopicTypeAndDirection) {
  const MessageLayout* l = find_layout("position", "PositionMeasurement", Direction::to_host);
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->id, 0x10);
  EXPECT_EQ(l->payload_size(), 32u);
  EXPECT_EQ(find_layout("position", "plexus::msg::PositionMeasurement", Direction::to_host), l);
  EXPECT_EQ(find_layout("position", "PositionMeasurement", Direction::to_device), nullptr);
  // The same topic name with two types: the type picks the message.
  ASSERT_NE(find_layout("truth/state", "Pose2D", Direction::to_host), nullptr);
  ASSERT_NE(find_layout("truth/state", "BalancingTruth", Direction::to_host), nullptr);
  EXPECT_EQ(find_layout("truth/state", "Pose2D", Direction::to_host)->id, 0x11);
  EXPECT_EQ(find_layout("truth/state", "BalancingTruth", Direction::to_host)->id, 0x22);
  EXPECT_EQ(find_layout("cmd", "UnicycleCommand", Direction::to_device)->id, 0x80);
  EXPECT_EQ(find_layout("gps", "PositionMeasurement", Direction::to_host), nullptr);
}

TEST(Protocol, SkidSteerFrames) {
  EXPECT_EQ(find_layout("gps", "Pose2D", Direction::to_host)->id, 0x30);
  EXPECT_EQ(find_layout("wheels", "TrackSpeeds", Direction::to_host)->id, 0x31);
  EXPECT_EQ(find_layout("imu", "Imu", Direction::to_host)->id, 0x20);  // the balancing robot's: six fields
  const MessageLayout* truth = find_layout("truth/state", "SkidSteerTruth", Direction::to_host);
  ASSERT_NE(truth, nullptr);
  EXPECT_EQ(truth->id, 0x32);
  EXPECT_EQ(truth->payload_size(), 80u);
  EXPECT_EQ(find_layout("cmd", "TrackCommand", Direction::to_device)->id, 0x82);
}

// The arm's frames carry one field per joint (`#`): sized for the arm's n joints in member
// order, and a 16-joint arm's truth (80 f64) fits a frame with its device time.
TEST(Protocol, JointFramesAreSizedForTheArm) {
  const MessageLayout* states = find_layout("joint_states", "JointState", Direction::to_host);
  ASSERT_NE(states, nullptr);
  EXPECT_TRUE(per_joint(*states));
  EXPECT_FALSE(per_joint(*find_layout(0x82)));
  const MessageLayout two = for_joints(*states, 2);
  std::vector<std::string> names;
  for (const auto& f : two.fields) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"phi1", "phi2", "dphi1", "dphi2", "tau1", "tau2"}));
  EXPECT_FALSE(per_joint(two));
  EXPECT_EQ(joints_in(*states, {"phi1", "phi2", "phi3", "dphi1", "dphi2", "dphi3"}), 3u);
  EXPECT_EQ(joints_in(*states, {"phi2", "dphi1"}), 0u);   // a run from 1
  EXPECT_EQ(joints_in(*find_layout(0x82), {"v_l"}), 0u);  // no per-joint field
  const MessageLayout* truth = find_layout("truth/state", "FlexibleJointTruth", Direction::to_host);
  ASSERT_NE(truth, nullptr);
  EXPECT_EQ(for_joints(*truth, kMaxJoints).payload_size(), 640u);
  EXPECT_LE(for_joints(*truth, kMaxJoints).payload_size() + 8, kMaxPayload);
  EXPECT_LE(for_joints(*truth, kMaxJoints).fields.size(), kMaxFields);
  EXPECT_EQ(for_joints(*find_layout("cmd", "JointCommand", Direction::to_device), 16).payload_size(), 128u);
}

TEST(Protocol, StopHasNoPayload) {
  const MessageLayout* stop = find_layout(kStopId);
  ASSERT_NE(stop, nullptr);
  EXPECT_EQ(stop->payload_size(), 0u);
  EXPECT_EQ(stop->direction, Direction::to_device);
}

// A device's own wire types (docs/bridges.md, "A device's own frames"): an encoder board's
// frame with an f32 and scaled integers, worked by hand.
TEST(Protocol, WireTypesEncodeAndDecodeLittleEndian) {
  MessageLayout l;
  l.fields = {{"a", WireKind::f32, 1.0},  {"b", WireKind::i16, 0.001}, {"c", WireKind::u8, 1.0},
              {"d", WireKind::i32, 1e-4}, {"e", WireKind::u16, 0.5},   {"f", WireKind::i8, 1.0},
              {"g", WireKind::u32, 1.0},  {"h", WireKind::f64, 1.0}};
  EXPECT_EQ(l.payload_size(), 4u + 2 + 1 + 4 + 2 + 1 + 4 + 8);
  const double in[] = {1.5, -1.2344, 200.0, 0.12345, 3.3, -7.0, 70000.0, -2.25};
  uint8_t p[kMaxPayload] = {};
  ASSERT_EQ(l.encode(in, p), l.payload_size());
  // 1.5f = 0x3FC00000; -1234 = 0xFB2E; 200; 1234 (0.12345 / 1e-4 = 1234.5 rounds to even) = 0x04D2;
  // 3.3 / 0.5 = 6.6 -> 7; -7 = 0xF9; 70000 = 0x00011170; -2.25 = 0xC002000000000000.
  const Bytes expected = {0x00, 0x00, 0xC0, 0x3F, 0x2E, 0xFB, 0xC8, 0xD2, 0x04, 0x00, 0x00, 0x07, 0x00,
                          0xF9, 0x70, 0x11, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0xC0};
  EXPECT_EQ(Bytes(p, p + l.payload_size()), expected);
  double out[8];
  l.decode(p, out);
  EXPECT_EQ(out[0], 1.5);
  EXPECT_NEAR(out[1], -1.234, 1e-12);  // within the scale's half step of -1.2344
  EXPECT_EQ(out[2], 200.0);
  EXPECT_NEAR(out[3], 0.1234, 1e-12);
  EXPECT_EQ(out[4], 3.5);
  EXPECT_EQ(out[5], -7.0);
  EXPECT_EQ(out[6], 70000.0);
  EXPECT_EQ(out[7], -2.25);
}

TEST(Protocol, IntegersSaturateAndNonFiniteIsZero) {
  MessageLayout l;
  l.fields = {{"a", WireKind::i16, 0.001}, {"b", WireKind::u8, 1.0}, {"c", WireKind::i8, 1.0}};
  const double in[] = {40.0, -3.0, std::numeric_limits<double>::quiet_NaN()};
  uint8_t p[kMaxPayload] = {};
  l.encode(in, p);
  double out[3];
  l.decode(p, out);
  EXPECT_NEAR(out[0], 32.767, 1e-12);  // 40 / 0.001 held at INT16_MAX
  EXPECT_EQ(out[1], 0.0);              // u8 holds no negative
  EXPECT_EQ(out[2], 0.0);
  WireKind k{};
  EXPECT_TRUE(parse_wire_kind("i16", k));
  EXPECT_EQ(k, WireKind::i16);
  EXPECT_FALSE(parse_wire_kind("f16", k));
}

// --- serial port (on a pseudo-terminal) ---------------------------------------------------

struct Pty {
  int master = -1, slave = -1;
  std::string path;
  Pty() {
    char name[256] = {};
    if (::openpty(&master, &slave, name, nullptr, nullptr) == 0) path = name;
  }
  ~Pty() {
    if (master >= 0) ::close(master);
    if (slave >= 0) ::close(slave);
  }
};

// Reads up to `n` bytes from `fd` within `timeout_ms`.
Bytes read_some(int fd, std::size_t n, int timeout_ms) {
  Bytes got;
  while (got.size() < n) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) break;
    uint8_t buf[256];
    const ssize_t r = ::read(fd, buf, std::min(sizeof buf, n - got.size()));
    if (r <= 0) break;
    got.insert(got.end(), buf, buf + r);
  }
  return got;
}

TEST(SerialPort, SupportedBauds) {
  for (long b : {115200L, 230400L, 460800L, 500000L, 576000L, 921600L, 1000000L}) EXPECT_TRUE(supported_baud(b)) << b;
  for (long b : {0L, 9600L, 57600L, 115201L, 1500000L, 2000000L, -115200L}) EXPECT_FALSE(supported_baud(b)) << b;
}

TEST(SerialPort, OpensAPtyAtSupportedRates) {
  Pty pty;
  ASSERT_FALSE(pty.path.empty()) << "openpty: " << std::strerror(errno);
  for (long baud : {115200L, 1000000L}) {
    std::string error;
    const int fd = open_serial(pty.path, baud, error);
    ASSERT_GE(fd, 0) << error;
    EXPECT_TRUE(error.empty());
    EXPECT_TRUE(::fcntl(fd, F_GETFL) & O_NONBLOCK);
    EXPECT_TRUE(::fcntl(fd, F_GETFD) & FD_CLOEXEC);
    ::close(fd);
  }
}

TEST(SerialPort, UnsupportedBaudNamesTheAllowedRates) {
  Pty pty;
  std::string error;
  EXPECT_EQ(open_serial(pty.path, 9600, error), -1);
  EXPECT_EQ(error,
            "serial device " + pty.path +
                ": unsupported baud rate 9600 (allowed: 115200, 230400, 460800, 500000, 576000, 921600, 1000000)");
}

TEST(SerialPort, MissingDeviceIsOneLine) {
  std::string error;
  EXPECT_EQ(open_serial("/nonexistent/ttyUSB9", 115200, error), -1);
  EXPECT_EQ(error, "serial device /nonexistent/ttyUSB9: cannot open: No such file or directory");
}

TEST(SerialPort, NotATerminal) {
  std::string error;
  EXPECT_EQ(open_serial("/dev/null", 115200, error), -1);
  EXPECT_EQ(error.rfind("serial device /dev/null: not a terminal", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

// Raw mode: the bytes a frame carries that a cooked tty would act on (NUL, NL, CR, ^C, ^D,
// XON, XOFF, DEL, ^Z, 0xFF) arrive unchanged both ways, and nothing is echoed.
TEST(SerialPort, RawBytesPassUnchangedWithoutEcho) {
  Pty pty;
  ASSERT_FALSE(pty.path.empty());
  std::string error;
  const int fd = open_serial(pty.path, 115200, error);
  ASSERT_GE(fd, 0) << error;
  ::fcntl(pty.master, F_SETFL, ::fcntl(pty.master, F_GETFL) | O_NONBLOCK);
  const Bytes special = {0x00, 0x0A, 0x0D, 0x03, 0x04, 0x11, 0x13, 0x7F, 0x1A, 0xFF, 0x00};

  ASSERT_EQ(::write(pty.master, special.data(), special.size()), static_cast<ssize_t>(special.size()));
  EXPECT_EQ(read_some(fd, special.size(), 1000), special);
  EXPECT_TRUE(read_some(pty.master, 1, 100).empty()) << "echoed";

  ASSERT_EQ(::write(fd, special.data(), special.size()), static_cast<ssize_t>(special.size()));
  EXPECT_EQ(read_some(pty.master, special.size(), 1000), special);  // no NL -> CR NL
  ::close(fd);
}

TEST(SerialPort, FrameThroughThePty) {
  Pty pty;
  std::string error;
  const int fd = open_serial(pty.path, 1000000, error);
  ASSERT_GE(fd, 0) << error;
  const Sent s{0x10, 42, Bytes(32, 0x00)};  // all zeros: the most stuffing
  const Bytes e = encode_frame(s);
  ASSERT_EQ(::write(pty.master, e.data(), e.size()), static_cast<ssize_t>(e.size()));
  Collect c;
  c.feed(read_some(fd, e.size(), 1000));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  ::close(fd);
}

// --- UDP --------------------------------------------------------------------------------

TEST(Udp, ParseEndpoint) {
  UdpEndpoint e;
  std::string error;
  ASSERT_TRUE(parse_endpoint("127.0.0.1:5000", "--device", e, error)) << error;
  EXPECT_EQ(e.address, "127.0.0.1");
  EXPECT_EQ(e.port, 5000);
  ASSERT_TRUE(parse_endpoint("0.0.0.0:1", "--local", e, error));
  EXPECT_EQ(e.port, 1);
  ASSERT_TRUE(parse_endpoint("192.168.1.20:65535", "--local", e, error));
  EXPECT_EQ(e.port, 65535);
}

TEST(Udp, ParseEndpointErrors) {
  for (const char* bad : {"", "127.0.0.1", "127.0.0.1:", ":5000", "127.0.0.1:0", "127.0.0.1:65536", "127.0.0.1:-1",
                          "127.0.0.1:+50", "127.0.0.1:50a", "127.0.0.1:000005000", "localhost:5000", "256.1.1.1:5000",
                          "127.0.0.1:5000:1", " 127.0.0.1:5000", "::1:5000"}) {
    UdpEndpoint e;
    std::string error;
    EXPECT_FALSE(parse_endpoint(bad, "--device", e, error)) << bad;
    EXPECT_EQ(error.rfind("--device: '" + std::string(bad) + "' ", 0), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  UdpEndpoint e;
  std::string error;
  parse_endpoint("127.0.0.1:70000", "--device", e, error);
  EXPECT_EQ(
      error,
      "--device: '127.0.0.1:70000' has no valid port 1..65535 ('70000') (expected IPV4:PORT, e.g. 127.0.0.1:5000)");
}

// Two sockets on loopback, each bound to its port and connected to the other's. Ports are
// fixed per test process (45000-45999) and moved on if another process holds one.
struct UdpPair {
  int a = -1, b = -1;
  UdpEndpoint ea, eb;
  std::string error;
  UdpPair() {
    const int first = static_cast<int>(::getpid() % 500);
    for (int attempt = 0; attempt < 50; ++attempt) {
      const int port = 45000 + ((first + attempt) % 500) * 2;
      ea = {"127.0.0.1", static_cast<uint16_t>(port)};
      eb = {"127.0.0.1", static_cast<uint16_t>(port + 1)};
      a = open_udp(ea, eb, error);
      if (a >= 0) {
        b = open_udp(eb, ea, error);
        if (b >= 0) return;
        ::close(a);
        a = -1;
      }
      if (error.find("Address already in use") == std::string::npos) return;  // not a clash: report it
    }
  }
  ~UdpPair() {
    if (a >= 0) ::close(a);
    if (b >= 0) ::close(b);
  }
};

TEST(Udp, TwoSocketsExchangeFrames) {
  UdpPair p;
  ASSERT_GE(p.b, 0) << p.error;
  EXPECT_TRUE(::fcntl(p.a, F_GETFL) & O_NONBLOCK);
  EXPECT_TRUE(::fcntl(p.a, F_GETFD) & FD_CLOEXEC);
  const Sent s{0x80, 9, Bytes(16, 0x3C)};
  const Bytes e = encode_frame(s);
  ASSERT_EQ(::send(p.a, e.data(), e.size(), 0), static_cast<ssize_t>(e.size()));
  Collect c;
  c.feed(read_some(p.b, e.size(), 1000));
  ASSERT_EQ(c.frames.size(), 1u);
  EXPECT_EQ(c.frames[0], s);
  ASSERT_EQ(::send(p.b, e.data(), e.size(), 0), static_cast<ssize_t>(e.size()));
  EXPECT_EQ(read_some(p.a, e.size(), 1000), e);
}

TEST(Udp, ConnectedSocketIgnoresStrangers) {
  UdpPair p;
  ASSERT_GE(p.b, 0) << p.error;
  const int stranger = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  ASSERT_GE(stranger, 0);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(p.eb.port);
  to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const uint8_t junk[3] = {1, 2, 3};
  EXPECT_EQ(::sendto(stranger, junk, sizeof junk, 0, reinterpret_cast<const sockaddr*>(&to), sizeof to), 3);
  EXPECT_TRUE(read_some(p.b, 3, 200).empty());
  ::close(stranger);
}

TEST(Udp, BindFailureIsOneLine) {
  std::string error;
  // TEST-NET-1 (RFC 5737) is never a local address.
  EXPECT_EQ(open_udp({"192.0.2.1", 45999}, {"127.0.0.1", 45998}, error), -1);
  EXPECT_EQ(error, "udp 192.0.2.1:45999: cannot bind: Cannot assign requested address");
}

TEST(Udp, PortTakenWithoutReuseIsReported) {
  // A socket without SO_REUSEADDR holds an ephemeral port; binding it again must fail.
  const int holder = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  ASSERT_GE(holder, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(holder, reinterpret_cast<const sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  ASSERT_EQ(::getsockname(holder, reinterpret_cast<sockaddr*>(&a), &len), 0);
  const uint16_t port = ntohs(a.sin_port);
  std::string error;
  EXPECT_EQ(open_udp({"127.0.0.1", port}, {"127.0.0.1", 45997}, error), -1);
  EXPECT_EQ(error, "udp 127.0.0.1:" + std::to_string(port) + ": cannot bind: Address already in use");
  ::close(holder);
}

}  // namespace
}  // namespace plexus::link
