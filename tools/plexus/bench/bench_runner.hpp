// `plexus bench`: runs a matrix (bench_matrix.hpp) and returns the run as run.json holds it
// (docs/qos-bench.md). One pair of bench_node processes per group of cells (vendor pair x
// transport x profile x topology) runs every size and rate of the group; the vendors' own
// tools (ddsperf, raw Fast DDS) run beside it on one host.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_matrix.hpp"

namespace plexus::cli::bench {

/// A delay planted in one cell (the reader spins before taking each of its pings in): the
/// check that --baseline finds a regression.
struct Plant {
  std::string cell;  ///< a cell id, e.g. "fast-fast/udp/latency/64/one_host"
  double delay_us = 0;
};

struct RunOptions {
  Matrix matrix;
  std::string out_dir;
  std::string command;  ///< as typed, for the report
  Plant plant;
};

/// Every cell of the matrix, in the order pair, transport, profile, size within each topology.
nlohmann::ordered_json run_bench(const RunOptions& o);

/// "pair/transport/profile/size/topology".
std::string cell_id(const std::string& pair, const std::string& transport, const std::string& profile, int size,
                    const std::string& topology);

}  // namespace plexus::cli::bench
