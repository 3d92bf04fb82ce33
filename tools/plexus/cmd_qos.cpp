#include "command.hpp"

namespace plexus::cli {

Command add_qos_command(CLI::App& root) {
  Command c;
  c.app = root.add_subcommand("qos", "(being written)");
  c.run = [] { return 1; };
  return c;
}

}  // namespace plexus::cli
