// `plexus bench`: a group's measurements made into the cells of run.json, one per payload
// size (docs/qos-bench.md, "How a cell is measured").
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_group.hpp"

namespace plexus::cli::bench {

/// The keys every cell has, run or not: id, pair, vendors, transport, profile, reliability,
/// size, topology, loss and delay (two_ns).
nlohmann::ordered_json cell_keys(const Group& g, int size, double loss, double delay_ms);

/// Why a group cannot run ("" if it can): shared memory beside Cyclone DDS or across the
/// namespaces, or the topology's own problem (no root).
std::string not_applicable(const Group& g, const std::string& topology_problem);

/// The cell of `size` from the group's runs (their samples pooled; the spread between
/// chunks and between runs). Recovery and the events go on the first size's cell.
nlohmann::ordered_json cell_of(const Group& g, int size, const std::vector<GroupRun>& runs, const Matrix& m,
                               bool first_size);

}  // namespace plexus::cli::bench
