// COBS as in Cheshire and Baker (1999) and the reference encoder of its Wikipedia article:
// a group of 254 non-zero bytes (code 0xFF) that ends the input is not followed by an empty
// group, so 254 non-zero bytes encode to 255 bytes, not 256.
#include "plexus/link/cobs.hpp"

namespace plexus::link {

std::size_t cobs_encode(const uint8_t* in, std::size_t n, uint8_t* out) {
  std::size_t code_at = 0;  // where the current group's code byte goes
  std::size_t o = 1;
  uint8_t code = 1;  // 1 + the group's data bytes so far
  for (std::size_t i = 0; i < n; ++i) {
    if (in[i] != 0) {
      out[o++] = in[i];
      ++code;
    }
    // A zero ends the group (the code byte stands for it); so do 254 data bytes, and then
    // the next group starts without a zero between them.
    if (in[i] == 0 || code == 0xFF) {
      out[code_at] = code;
      code = 1;
      if (in[i] == 0 || i + 1 < n) {
        code_at = o++;
      } else {
        return o;  // a full group ended the input: no empty group after it
      }
    }
  }
  out[code_at] = code;
  return o;
}

bool cobs_decode(const uint8_t* in, std::size_t n, uint8_t* out, std::size_t& out_n) {
  out_n = 0;
  // Every encoding has at least its first code byte: an empty block encodes nothing.
  if (n == 0) return false;
  std::size_t i = 0;
  while (i < n) {
    const uint8_t code = in[i++];
    if (code == 0) return false;
    if (code - 1u > n - i) return false;  // the group runs past the block
    for (uint8_t k = 1; k < code; ++k) {
      if (in[i] == 0) return false;
      out[out_n++] = in[i++];
    }
    // Each group but a full one (0xFF) and the last stands for a zero byte after its data.
    if (code != 0xFF && i < n) out[out_n++] = 0;
  }
  return true;
}

}  // namespace plexus::link
