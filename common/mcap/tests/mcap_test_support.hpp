// Helpers of the MCAP unit tests: temporary files and small recordings.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "plexus/base/input_error.hpp"
#include "plexus/mcap/reader.hpp"
#include "plexus/mcap/writer.hpp"

namespace plexus::mcap::test {

inline std::string temp_path(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->name()) + "_" + tag;  // a parameterised test's name holds '/'
  for (char& c : name)
    if (c == '/') c = '_';
  return (std::filesystem::temp_directory_path() / ("plexus_mcap_" + std::to_string(::getpid()) + "_" + name + ".mcap"))
      .string();
}

inline std::vector<unsigned char> read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const std::vector<unsigned char>& b, std::size_t n) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(n));
}

/// The payload of message i: a few bytes that say which message it is.
inline std::vector<unsigned char> payload(uint32_t i) {
  std::vector<unsigned char> p(8 + i % 13);
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = static_cast<unsigned char>(i * 31 + k);
  return p;
}

/// A recording of `n` messages on two channels (log time 1000 + 10 i, publish time 1000 + 10 i - 3),
/// small chunks so that it holds several. Returns the writer's statistics.
inline Statistics write_sample(const std::string& path, uint32_t n, Compression c = Compression::zstd,
                               std::size_t chunk_size = 1024, bool close = true) {
  WriterOptions o;
  o.compression = c;
  o.chunk_size = chunk_size;
  Writer w(path, o);
  const uint16_t s =
      w.add_schema("plexus::msg::Pose2D", "omgidl", "module plexus { module msg { struct Pose2D { double x; }; }; };");
  const uint16_t a = w.add_channel(s, "r1/pose", "cdr", {{"qos", "{\"reliability\":\"reliable\"}"}});
  const uint16_t b = w.add_channel(s, "r2/pose", "cdr", {});
  w.add_metadata("plexus", {{"recorder", "test"}});
  for (uint32_t i = 0; i < n; ++i) {
    const auto p = payload(i);
    w.write(i % 3 == 0 ? b : a, i, 1000 + 10ull * i, 1000 + 10ull * i - 3, p.data(), p.size());
  }
  if (close) w.close();
  return w.statistics();
}

/// Reads every message: (channel topic, sequence, log time, payload).
struct Read {
  std::string topic;
  uint32_t sequence;
  uint64_t log_time, publish_time;
  std::vector<unsigned char> data;
};
inline std::vector<Read> read_all(const Reader& r, uint64_t start = 0, uint64_t end = UINT64_MAX) {
  std::vector<Read> out;
  r.for_each_message(
      [&](const MessageView& m) {
        out.push_back({m.channel->topic, m.sequence, m.log_time, m.publish_time, {m.data, m.data + m.size}});
        return true;
      },
      start, end);
  return out;
}

template <class Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace plexus::mcap::test
