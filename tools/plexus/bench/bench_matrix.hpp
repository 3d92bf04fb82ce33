// `plexus bench`: the matrix of cells one run measures (docs/qos-bench.md), from a YAML
// file, a preset and flags. Validated here: every error is one line naming the file and key
// (or the flag), and the command exits 2.
#pragma once

#include <string>
#include <vector>

#include "plexus/runtime/vendor.hpp"

namespace plexus::cli::bench {

/// A writer vendor and a reader vendor: "fast-cyclone" writes with Fast DDS, reads with Cyclone DDS.
struct VendorPair {
  rt::Vendor writer = rt::Vendor::fast, reader = rt::Vendor::fast;
  std::string name() const;
};

struct Matrix {
  std::vector<VendorPair> pairs;
  std::vector<std::string> transports;  ///< "udp", "shm"
  std::vector<std::string> profiles;    ///< QoS profile names in qos_file
  std::vector<int> sizes;               ///< payload bytes, 0..1 MiB
  std::vector<double> rates_hz;         ///< ping rates; 0 = unpaced; the first > 0 is the headline
  std::vector<std::string> topologies;  ///< "one_host", "two_ns"
  double loss_percent = 1;              ///< packet loss on the two_ns link
  double delay_ms = 0;                  ///< delay each way on the two_ns link (link_delay; 0: none)
  double outage_s = 0.2;                ///< the burst phase's cut (two_ns)
  double seconds_per_phase = 1.0;       ///< each latency phase
  double throughput_seconds = 1.0;      ///< each throughput phase (0: none)
  int repeats = 1;                      ///< every group this many times (the spread between them)
  bool vendor_tools = true;             ///< ddsperf and raw Fast DDS beside plexus
  /// Where the writer and the reader run, alike for plexus and the vendors' tools: "split"
  /// (writer on the first allowed CPU, reader on the second), "same" (both on the first) or
  /// "none". On this 2-vCPU machine the placement alone moved a round trip by about 30 us a
  /// hop (docs/performance.md, Ping-pong): pinned alike, the ratios compare the paths.
  std::string pin = "split";
  std::string qos_file;  ///< the profiles (deploy/qos.yaml, plus inline ones)
  /// The DDS domain of every group and vendor tool: they run one after the other, and each
  /// group's processes are gone before the next starts.
  int domain = 200;

  /// The first rate > 0 (the summary's), or 0 when every rate is unpaced.
  double headline_rate() const;
};

/// The built-in presets: "quick" (CI: two vendors, two sizes, a few seconds) and "full"
/// (3 vendor pairs x 2 transports x 3 profiles x 4 sizes x 2 topologies).
Matrix preset(const std::string& name);

/// Reads a matrix file over `base` (its keys replace the preset's). Inline profiles (a list
/// entry that is a mapping with a `name`) are written, with the named file's, into
/// `out_dir`/qos.yaml, which becomes qos_file. Throws InputError naming the file and key.
Matrix load_matrix(const std::string& path, Matrix base, const std::string& out_dir);

/// Checks every value (and that each profile exists in qos_file); InputError naming `origin`.
void validate(const Matrix& m, const std::string& origin);

/// Parsers for the flags (and the file's lists): InputError naming `origin` on a bad entry.
std::vector<VendorPair> parse_pairs(const std::vector<std::string>& names, const std::string& origin);

}  // namespace plexus::cli::bench
