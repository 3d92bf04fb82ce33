// `plexus bench`: one group of cells (a vendor pair, transport, profile and topology, every
// size and rate) run by a bench_node writer and reader (tools/latency/bench_node.cpp), and
// what they measured, before it becomes cells (bench_cells.hpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_matrix.hpp"
#include "plexus/runtime/qos.hpp"

namespace plexus::cli::bench {

class NetnsPair;
struct Plant;

/// One vendor pair, transport, profile and topology: the cells one process pair measures.
struct Group {
  VendorPair pair;
  std::string transport, profile, topology;
  rt::QosProfile qos;
  int domain = 0;
  std::string pair_name() const { return pair.name(); }
};

/// What a group's run measured at one payload size: samples (us) by rate, the throughput
/// phase's counts, CPU.
struct SizeResult {
  std::map<double, std::vector<double>> oneway_raw_us, rtt_us;  ///< by rate
  std::map<double, long> sent, received;
  long flood_sent = 0, flood_received = 0;
  double flood_bytes = 0, flood_window_s = 0, flood_wall_s = 0;
  /// CPU seconds of each end and the writer's phase time: per rate, and of the flood.
  struct Cpu {
    double writer_s = 0, reader_s = 0, wall_s = 0;
  };
  std::map<double, Cpu> cpu;
  Cpu flood_cpu;
};

/// The CPUs of the writer and the reader (-1: not pinned), from Matrix::pin.
struct Placement {
  int writer = -1, reader = -1;
};

/// One run of a group: by payload size, with the clock offset (reader minus writer), the
/// burst's recovery and the reader's event times (null when none came).
struct GroupRun {
  bool ok = false;
  std::string reason;
  std::map<int, SizeResult> sizes;
  double offset_us = 0;
  nlohmann::ordered_json recovery, deadline_after, liveliness_after;
};

/// The CPUs of the writer and the reader from Matrix::pin: split, same or none.
Placement placement(const std::string& pin);

/// Runs the group once: its reader (in the second namespace with `ns`), then its writer
/// (in the first), both pinned per the matrix; the samples go through `dir`. A planted delay
/// applies to pings of `size_to_delay` bytes (-1: none). Not ok, with the reason, when the
/// writer found no reader or a result is missing.
GroupRun run_group(const Group& g, const Matrix& m, const NetnsPair* ns, const Plant& plant, const std::string& dir,
                   int size_to_delay);

/// A file's text ("" if unreadable).
std::string read_file(const std::string& path);

}  // namespace plexus::cli::bench
