// Benchmarks of the shared algorithm helpers.
#include <benchmark/benchmark.h>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/unicycle/unicycle_plant.hpp"

namespace {

using namespace plexus::algorithms;

void BM_UnicyclePlantStep(benchmark::State& state) {
  UnicycleState s;
  const UnicycleInput u{1.0, 0.3};
  for (auto _ : state) {
    s = unicycle_step(s, u, 0.01);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_UnicyclePlantStep);

}  // namespace
