// plexus: the command-line tool. Each subcommand is in its own cmd_<name>.cpp.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "command.hpp"
#include "plexus/base/cli_style.hpp"
#include "plexus/base/input_error.hpp"
#include "plexus/base/logging.hpp"
#include "plexus/scenario/plugins.hpp"

int main(int argc, char** argv) {
  CLI::App app{"plexus: distributed real-time runtime for robot estimation and control"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("plexus ") + PLEXUS_VERSION);
  // Accepted before or after the subcommand: `plexus topic echo r1/contact --plugin libmylab_msgs.so`.
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins,
                 "Load a shared library of a user's component, service or message types first (docs/sdk.md); "
                 "repeatable");
  app.fallthrough();

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
  commands.push_back(plexus::cli::add_bench_command(app));
  commands.push_back(plexus::cli::add_deploy_command(app));
  commands.push_back(plexus::cli::add_service_command(app));
  commands.push_back(plexus::cli::add_param_command(app));
  // Further subcommands register here.

  // An unknown first word is named, with the commands there are (CLI11 would only say that
  // a subcommand is required).
  std::string known;
  bool found = false;
  for (const auto* sub : app.get_subcommands({})) {
    known += (known.empty() ? "" : ", ") + sub->get_name();
    found = found || (argc > 1 && sub->check_name(argv[1]));
  }
  if (argc > 1 && argv[1][0] != '-' && !found) {
    std::fprintf(stderr, "plexus: unknown command '%s' (commands: %s)\n", argv[1], known.c_str());
    return plexus::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 exits 0 for --help and 106/109... for usage errors: usage errors are bad input,
    // exit 2, with a one-line error under the same prefix as the others.
    std::string cmd = "plexus";
    for (const auto* sub : app.get_subcommands()) cmd += " " + sub->get_name();
    return plexus::parse_error_exit(app, e, cmd);
  }
  // One prefix for every error line: "plexus <command>: ".
  std::string prefix = "plexus";
  for (auto& c : commands)
    if (c.app->parsed()) prefix += " " + c.app->get_name();
  try {
    // Every log line of every command on stderr, in the one format (stdout carries --json).
    plexus::init_logging(prefix, "", "warn");
    for (const auto& lib : plugins) plexus::scenario::load_plugin(lib, "--plugin");
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const plexus::InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", prefix.c_str(), e.what());
    return plexus::kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: error: out of memory (a run too long, or an input too large, for this machine)\n",
                 prefix.c_str());
    return plexus::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: failed: %s\n", prefix.c_str(), e.what());
    return 1;
  }
  return 1;
}
