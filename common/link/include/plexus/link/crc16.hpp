// CRC-16 of the bridge frames (docs/bridges.md): CRC-16/CCITT-FALSE, also catalogued as
// CRC-16/IBM-3740. Polynomial 0x1021 (x^16 + x^12 + x^5 + 1), initial value 0xFFFF, input
// and output not reflected, final XOR 0x0000. Check value: crc16("123456789") = 0x29B1.
#pragma once

#include <cstddef>
#include <cstdint>

namespace plexus::link {

inline constexpr uint16_t kCrc16Init = 0xFFFF;

/// CRC over `n` bytes, continuing from `crc` (kCrc16Init for a fresh computation).
uint16_t crc16(const uint8_t* data, std::size_t n, uint16_t crc = kCrc16Init);

}  // namespace plexus::link
