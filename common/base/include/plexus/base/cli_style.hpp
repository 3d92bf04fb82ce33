// The command-line style every plexus program shares (docs/tools.md, "One CLI style").
#pragma once

#include <sched.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace plexus {

/// A command-line error: "<program>: error: <what> (--help lists the options)", one line,
/// exit 2. --help and --version print and exit 0.
inline int parse_error_exit(CLI::App& app, const CLI::ParseError& e, const std::string& program) {
  if (e.get_exit_code() == 0) return app.exit(e);
  std::fprintf(stderr, "%s: error: %s (--help lists the options)\n", program.c_str(), e.what());
  return 2;
}

/// An option that must be a finite number > 0 ("--step: must be > 0 s (got -0.01)"); `unit`
/// names what it counts ("s", "Hz").
inline CLI::Validator positive(const std::string& unit) {
  return CLI::Validator(
      [unit](std::string& v) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        if (end == v.c_str() || *end != '\0' || !std::isfinite(x) || x <= 0.0)
          return "must be > 0 " + unit + " (got " + v + ")";
        return {};
      },
      unit == "s" ? "SECONDS > 0" : unit + " > 0");
}

/// A realtime program's --priority: SCHED_FIFO 1 .. 99, or 0 for normal scheduling.
inline CLI::Validator fifo_priority() { return CLI::Range(0, 99); }

/// A realtime program's --cpu: the CPU to pin to, 0 .. CPU_SETSIZE - 1 (no negative "none":
/// without the option nothing is pinned).
inline CLI::Validator cpu_index() { return CLI::Range(0, CPU_SETSIZE - 1); }

}  // namespace plexus
