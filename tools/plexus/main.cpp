// plexus: the command-line tool. Each subcommand is in its own cmd_<name>.cpp.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <vector>

#include "command.hpp"
#include "plexus/base/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"plexus: distributed real-time runtime for robot estimation and control"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "plexus 0.1.0");

  std::vector<plexus::cli::Command> commands;
  commands.push_back(plexus::cli::add_demo_command(app));
  commands.push_back(plexus::cli::add_qos_command(app));
  commands.push_back(plexus::cli::add_launch_command(app));
  commands.push_back(plexus::cli::add_sim_command(app));
  commands.push_back(plexus::cli::add_report_command(app));
  commands.push_back(plexus::cli::add_topic_command(app));
  commands.push_back(plexus::cli::add_record_command(app));
  commands.push_back(plexus::cli::add_replay_command(app));
  commands.push_back(plexus::cli::add_latency_command(app));
  // Further subcommands register here.

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 exits 0 for --help and 106/109... for usage errors: usage errors are bad input, exit 2.
    const int code = app.exit(e);
    return code == 0 ? 0 : plexus::kExitBadInput;
  }
  try {
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const plexus::InputError& e) {
    std::fprintf(stderr, "plexus: error: %s\n", e.what());
    return plexus::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plexus: failed: %s\n", e.what());
    return 1;
  }
  return 1;
}
