#include "plexus/scenario/digest.hpp"

#include <cstdio>

namespace plexus::scenario {

uint64_t run_digest(const RunLog& log) {
  uint64_t h = kFnv1aOffset;
  for (const auto& trace : log.signals) {
    if (!trace.spec.plant_state) continue;
    const std::size_t w = trace.width();
    for (std::size_t row = 0; row < trace.size(); ++row) {
      h = fnv1a64(&trace.steps[row], sizeof(int64_t), h);
      h = fnv1a64(&trace.values[row * w], w * sizeof(double), h);
    }
  }
  return h;
}

uint64_t derive_seed(uint64_t scenario_seed, const std::string& name) {
  // splitmix64 finaliser over the scenario seed mixed with the name's hash.
  uint64_t z = scenario_seed ^ fnv1a64(name.data(), name.size());
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return (z ^ (z >> 31)) >> 1;  // 63 bits: a seed the scenario format can state (0 .. 2^63-1)
}

}  // namespace plexus::scenario
