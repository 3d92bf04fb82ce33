// Little-endian fields of MCAP records: Builder appends them, Cursor reads them within
// bounds (internal).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "plexus/mcap/records.hpp"

namespace plexus::mcap::detail {

/// A record or field that does not parse: what is wrong and the byte offset (in the file
/// or, for records inside a chunk, in the chunk's uncompressed records) where it starts.
class FormatError : public std::runtime_error {
 public:
  FormatError(const std::string& what, uint64_t offset) : std::runtime_error(what), offset_(offset) {}
  uint64_t offset() const { return offset_; }

 private:
  uint64_t offset_;
};

class Builder {
 public:
  explicit Builder(std::vector<unsigned char>& out) : out_(out) {}
  void u8(uint8_t v) { out_.push_back(v); }
  void u16(uint16_t v) { le(v, 2); }
  void u32(uint32_t v) { le(v, 4); }
  void u64(uint64_t v) { le(v, 8); }
  void raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    out_.insert(out_.end(), b, b + n);
  }
  void str(std::string_view s) {
    u32(static_cast<uint32_t>(s.size()));
    raw(s.data(), s.size());
  }
  void string_map(const std::map<std::string, std::string>& m) {
    const std::size_t at = begin_u32();
    for (const auto& [k, v] : m) {
      str(k);
      str(v);
    }
    end_u32(at);
  }
  /// Opcode and a length to be filled in by end_record; returns where the length goes.
  std::size_t begin_record(Op op) {
    u8(static_cast<uint8_t>(op));
    const std::size_t at = out_.size();
    u64(0);
    return at;
  }
  void end_record(std::size_t at) { put_le(at, out_.size() - at - 8, 8); }
  /// A uint32 byte length (of a map or an array) to be filled in by end_u32.
  std::size_t begin_u32() {
    const std::size_t at = out_.size();
    u32(0);
    return at;
  }
  void end_u32(std::size_t at) { put_le(at, out_.size() - at - 4, 4); }

 private:
  void le(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(static_cast<unsigned char>(v >> (8 * i)));
  }
  void put_le(std::size_t at, uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_[at + static_cast<std::size_t>(i)] = static_cast<unsigned char>(v >> (8 * i));
  }
  std::vector<unsigned char>& out_;
};

/// Reads fields from [p, p + n); `base` is the offset of p in the file (or chunk) for errors.
class Cursor {
 public:
  Cursor(const unsigned char* p, std::size_t n, uint64_t base, const char* what)
      : p_(p), n_(n), base_(base), what_(what) {}
  std::size_t remaining() const { return n_ - at_; }
  uint64_t offset() const { return base_ + at_; }
  uint8_t u8() { return static_cast<uint8_t>(le(1)); }
  uint16_t u16() { return static_cast<uint16_t>(le(2)); }
  uint32_t u32() { return static_cast<uint32_t>(le(4)); }
  uint64_t u64() { return le(8); }
  /// n bytes in place.
  const unsigned char* take(uint64_t n, const char* field) {
    if (n > remaining())
      throw FormatError(std::string(what_) + " record: " + field + " of " + std::to_string(n) +
                            " bytes runs past the record (" + std::to_string(remaining()) + " left)",
                        offset());
    const unsigned char* at = p_ + at_;
    at_ += static_cast<std::size_t>(n);
    return at;
  }
  std::string str(const char* field) {
    const uint32_t n = u32();
    const auto* s = take(n, field);
    return std::string(reinterpret_cast<const char*>(s), n);
  }
  std::map<std::string, std::string> string_map(const char* field) {
    const uint32_t n = u32();
    Cursor m(take(n, field), n, offset() - n, what_);
    std::map<std::string, std::string> out;
    while (m.remaining() > 0) {
      std::string k = m.str(field);
      out[k] = m.str(field);
    }
    return out;
  }
  template <class K>
  std::map<K, uint64_t> id_u64_map(const char* field) {
    const uint32_t n = u32();
    Cursor m(take(n, field), n, offset() - n, what_);
    std::map<K, uint64_t> out;
    while (m.remaining() > 0) {
      const K k = static_cast<K>(m.le(sizeof(K)));
      out[k] = m.u64();
    }
    return out;
  }

 private:
  uint64_t le(int n) {
    if (static_cast<std::size_t>(n) > remaining())
      throw FormatError(std::string(what_) + " record ends inside a field (" + std::to_string(remaining()) +
                            " bytes left, " + std::to_string(n) + " needed)",
                        offset());
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(p_[at_ + static_cast<std::size_t>(i)]) << (8 * i);
    at_ += static_cast<std::size_t>(n);
    return v;
  }
  const unsigned char* p_;
  std::size_t n_;
  std::size_t at_ = 0;
  uint64_t base_;
  const char* what_;
};

}  // namespace plexus::mcap::detail
