#include "framework/cli/commands.hpp"
#include "framework/harness/status_line.hpp"

namespace hystbench::cli {

void add_quiet_option(CLI::App& command) {
  command.add_flag_callback("--quiet", [] { set_quiet(true); },
                            "no progress display (on a terminal a status line; in a log a "
                            "timestamped line at least once a minute)");
}

}  // namespace hystbench::cli
