// Consistent Overhead Byte Stuffing (Cheshire and Baker, IEEE/ACM Trans. Networking 7(2),
// 1999): removes every 0x00 from a block so that 0x00 can delimit frames on a byte stream.
// The encoded block is at most cobs_max_encoded(n) bytes and holds no zero byte; the frame
// delimiter itself is not written by these functions.
#pragma once

#include <cstddef>
#include <cstdint>

namespace plexus::link {

constexpr std::size_t cobs_max_encoded(std::size_t n) { return n + n / 254 + 1; }

/// Encodes `n` bytes of `in` into `out` (room for cobs_max_encoded(n)); returns the bytes
/// written. No delimiter is appended.
std::size_t cobs_encode(const uint8_t* in, std::size_t n, uint8_t* out);

/// Decodes an encoded block (without its delimiter) into `out` (room for `n` bytes).
/// Returns false for a malformed block: a zero byte inside it, or a code byte that points
/// past its end; `out_n` is then unspecified.
bool cobs_decode(const uint8_t* in, std::size_t n, uint8_t* out, std::size_t& out_n);

}  // namespace plexus::link
