// Deterministic sample contents for any message type, for cross-process tests.
// The payload after the header is a byte pattern that depends on the type and the
// sequence number; every double it produces is finite. Generic over TypeSupport.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "plexus/base/clock.hpp"
#include "plexus/msg/messages.hpp"

namespace plexus::test {

inline constexpr std::size_t kHeaderEnd = 4 + 32;  // encapsulation + StampHeader

inline unsigned char pattern_byte(std::size_t i, uint64_t seq, std::size_t type_salt) {
  return static_cast<unsigned char>(0x30 + (i * 7 + seq * 13 + type_salt) % 64);
}

inline std::size_t type_salt(const char* name) {
  std::size_t h = 0;
  for (const char* p = name; *p; ++p) h = h * 31 + static_cast<unsigned char>(*p);
  return h % 64;
}

/// Fills `sample` (a T described by ts): header seq_num = seq, times = now, and the
/// payload pattern for seq. Every message starts with its StampHeader, so the header is
/// at a fixed offset of the (little-endian) CDR.
inline void fill_pattern(const msg::TypeSupport& ts, void* sample, uint64_t seq) {
  std::vector<unsigned char> buf(ts.max_cdr_size);
  const std::size_t n = ts.serialize(sample, buf.data(), buf.size());
  const int64_t now = wall_time_ns();
  std::memcpy(buf.data() + 4, &seq, 8);       // seq_num
  std::memcpy(buf.data() + 4 + 8, &now, 8);   // data_time_ns
  std::memcpy(buf.data() + 4 + 16, &now, 8);  // origin_time_ns
  std::memcpy(buf.data() + 4 + 24, &now, 8);  // publish_time_ns
  const std::size_t salt = type_salt(ts.type_name);
  for (std::size_t i = kHeaderEnd; i < n; ++i) buf[i] = pattern_byte(i, seq, salt);
  ts.deserialize(buf.data(), n, sample);
}

/// True if the payload of `sample` is the pattern for its header's seq_num. Compares
/// canonical encodings (the pattern re-encoded), so alignment padding does not count.
/// Overwrites `sample`.
inline bool matches_pattern(const msg::TypeSupport& ts, void* sample) {
  std::vector<unsigned char> got(ts.max_cdr_size);
  const std::size_t n = ts.serialize(sample, got.data(), got.size());
  if (n < kHeaderEnd) return false;
  uint64_t seq = 0;
  std::memcpy(&seq, got.data() + 4, 8);
  std::vector<unsigned char> want(got.begin(), got.begin() + static_cast<std::ptrdiff_t>(n));
  const std::size_t salt = type_salt(ts.type_name);
  for (std::size_t i = kHeaderEnd; i < n; ++i) want[i] = pattern_byte(i, seq, salt);
  if (!ts.deserialize(want.data(), n, sample)) return false;
  const std::size_t m = ts.serialize(sample, want.data(), want.size());
  return seq != 0 && m == n && std::memcmp(want.data(), got.data(), n) == 0;
}

}  // namespace plexus::test
