// A `plexus` subcommand: each one lives in its own cmd_<name>.cpp and registers itself
// with main.cpp through an add_<name>_command(CLI::App&) function.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "plexus/base/cli_style.hpp"

namespace plexus::cli {

struct Command {
  CLI::App* app = nullptr;   ///< the subcommand; main runs `run` when it was given
  std::function<int()> run;  ///< returns the process exit code; may throw InputError (exit 2)
};

Command add_demo_command(CLI::App& root);
Command add_qos_command(CLI::App& root);
Command add_launch_command(CLI::App& root);
Command add_sim_command(CLI::App& root);
Command add_report_command(CLI::App& root);
Command add_topic_command(CLI::App& root);
Command add_record_command(CLI::App& root);
Command add_replay_command(CLI::App& root);
Command add_latency_command(CLI::App& root);
Command add_bench_command(CLI::App& root);
Command add_deploy_command(CLI::App& root);
Command add_service_command(CLI::App& root);
Command add_param_command(CLI::App& root);

/// A duration option that must be > 0 s (a zero or negative wait or timeout is refused,
/// exit 2: "--timeout: must be > 0 s (got -1)").
inline CLI::Validator positive_seconds() { return positive("s"); }

}  // namespace plexus::cli
