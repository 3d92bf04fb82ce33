// `plexus bench`: the machine a run measured (docs/qos-bench.md, run.json's "machine").
#pragma once

#include <nlohmann/json.hpp>

namespace plexus::cli::bench {

/// hostname, cpu_model, cpus, kernel, memory_mb, load_before (now), and the DDS and plexus
/// versions (Debian's package versions; "unknown" without dpkg).
nlohmann::ordered_json machine();

/// The 1, 5 and 15 minute load averages.
nlohmann::ordered_json load_average();

}  // namespace plexus::cli::bench
