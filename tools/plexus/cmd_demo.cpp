#include "command.hpp"

namespace plexus::cli {

Command add_demo_command(CLI::App& root) {
  Command c;
  c.app = root.add_subcommand("demo", "(being written)");
  c.run = [] { return 1; };
  return c;
}

}  // namespace plexus::cli
