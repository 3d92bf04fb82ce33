// plexus report RUN_DIR: PNG plots of a run folder's signals and a markdown table of its
// metrics against the scenario's expectations (RUN_DIR/report.md, RUN_DIR/plots/*.png).
// Exit codes: 0 every expectation met, 1 a FAIL row, 2 not a run folder.
#include <cstdio>
#include <memory>
#include <string>

#include "command.hpp"
#include "run_result.hpp"

namespace plexus::cli {

Command add_report_command(CLI::App& root) {
  auto dir = std::make_shared<std::string>();
  Command c;
  c.app = root.add_subcommand("report",
                              "Plot a run folder written by `plexus sim` (gnuplot PNGs) and tabulate its metrics");
  c.app->add_option("run_dir", *dir, "Run folder")->required();
  // Exit 1 when a row says FAIL (an expectation not met, or its metric missing), as `sim`.
  c.run = [dir] { return print_report(*dir) > 0 ? 1 : 0; };
  return c;
}

}  // namespace plexus::cli
