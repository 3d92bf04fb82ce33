// `plexus latency loop`: wake-up lateness of a plexus PeriodicLoop against cyclictest, measured
// the same way for both (same CPU, same settings, interleaved rounds, same 1 us histogram).
#pragma once

#include <cstdint>
#include <string>

namespace plexus::cli {

struct LoopOpts {
  double rate = 1000, duration = 10;
  int priority = 80;
  /// Both run pinned to this CPU. -1: the first CPU this process may run on, the CPU cyclictest
  /// pins its thread to when given no -a (it always pins), so both still run on the same CPU.
  int cpu = -1;
  int cpu_dma_latency = 0;  // us, as cyclictest's default; -1: no request (cyclictest --laptop)
  int64_t timer_slack = 1;  // ns; 0 keeps the thread's (Linux default 50 us)
  /// The duration is split into this many plexus and cyclictest segments, run alternately
  /// (ABBA order), so a change in the shared machine's load hits both alike.
  int rounds = 4;
  std::string out;
  bool json = false, no_cyclictest = false, no_mlock = false;
};

/// Runs the measurement and prints the table (or one JSON object). InputError for bad options.
int run_loop(const LoopOpts& o);

}  // namespace plexus::cli
