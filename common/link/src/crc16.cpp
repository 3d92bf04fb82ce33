// CRC-16/CCITT-FALSE, one table lookup per byte. The table is built at compile time, so the
// receive path neither allocates nor initialises anything at run time.
#include "plexus/link/crc16.hpp"

#include <array>

namespace plexus::link {
namespace {

constexpr uint16_t kPoly = 0x1021;

// Entry b: the CRC register after shifting the byte b through it, MSB first (no reflection).
constexpr std::array<uint16_t, 256> make_table() {
  std::array<uint16_t, 256> t{};
  for (unsigned b = 0; b < 256; ++b) {
    uint16_t r = static_cast<uint16_t>(b << 8);
    for (int bit = 0; bit < 8; ++bit) r = static_cast<uint16_t>((r & 0x8000) ? (r << 1) ^ kPoly : r << 1);
    t[b] = r;
  }
  return t;
}

constexpr std::array<uint16_t, 256> kTable = make_table();

}  // namespace

uint16_t crc16(const uint8_t* data, std::size_t n, uint16_t crc) {
  for (std::size_t i = 0; i < n; ++i) crc = static_cast<uint16_t>((crc << 8) ^ kTable[((crc >> 8) ^ data[i]) & 0xFF]);
  return crc;
}

}  // namespace plexus::link
