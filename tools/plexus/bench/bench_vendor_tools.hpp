// `plexus bench`: the vendors' own tools beside plexus, one host, same vendor on both ends
// (docs/qos-bench.md): raw Fast DDS (tools/latency/raw_fast_pingpong.cpp) and ddsperf.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_group.hpp"

namespace plexus::cli::bench {

struct VendorResult {
  std::string name;
  nlohmann::ordered_json round_trip, throughput;  ///< null when not measured
};

/// Round trips of raw_fast_pingpong at the group's reliability, depth and transport, `size`
/// bytes at `rate` (0: back to back), placed as the matrix says; the samples through `dir`.
VendorResult raw_fast_baseline(const Group& g, int size, double rate, const Matrix& m, const std::string& dir);

/// ddsperf ping/pong round trips at `rate`, and pub/sub saturation (the fastest whole
/// second), reliable unless the group is best effort.
VendorResult ddsperf_baseline(const Group& g, int size, double rate, const Matrix& m);

}  // namespace plexus::cli::bench
