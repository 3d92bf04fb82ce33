// plexus report RUN_DIR: PNG plots of a run folder's signals and a markdown table of its
// metrics against the scenario's expectations (RUN_DIR/report.md, RUN_DIR/plots/*.png).
#include <cstdio>
#include <memory>
#include <string>

#include "command.hpp"
#include "run_result.hpp"

namespace plexus::cli {

Command add_report_command(CLI::App& root) {
  auto dir = std::make_shared<std::string>();
  Command c;
  c.app = root.add_subcommand("report", "Plot a run folder written by `plexus sim` (gnuplot PNGs) and tabulate its metrics");
  c.app->add_option("run_dir", *dir, "Run folder")->required();
  c.run = [dir] {
    print_report(*dir);
    return 0;
  };
  return c;
}

}  // namespace plexus::cli
