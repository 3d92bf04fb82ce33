// Cyclone DDS's own benchmark, ddsperf, as the baseline of `plexus latency pingpong` and
// `plexus bench`: its configuration (loopback, or one interface with unicast peers) and the
// parsing of what it prints.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace plexus::cli {

/// "CYCLONEDDS_URI=..." for ddsperf on `interface` with these unicast discovery peers (no
/// multicast), as plexus's own Cyclone participants are configured.
std::string ddsperf_uri(const std::string& interface = "127.0.0.1",
                        const std::vector<std::string>& peers = {"127.0.0.1"});

/// ddsperf ping prints, per second: "... size N mean Xus min Xus 50% Xus 90% Xus 99% Xus max
/// Xus cnt N" (half round trips). Returns the pingpong result object (implementation,
/// received, rtt_mean_us, rtt_p50_us, rtt_p90_us, rtt_p99_us, rtt_max_us, note): percentiles
/// are the count-weighted mean of the per-second values, doubled to round trips; max is the
/// max. Throws std::runtime_error if there is no latency line.
nlohmann::ordered_json parse_ddsperf_ping(const std::string& out);

/// ddsperf sub prints, per second: "... size N total N lost N delta N lost N rate X kS/s Y
/// Mb/s ...". Returns {"samples_per_s", "mb_per_s", "lost"} of the fastest second (the
/// saturation rate), or null if there is no such line.
nlohmann::ordered_json parse_ddsperf_sub(const std::string& out);

}  // namespace plexus::cli
