// The subcommands of `hystbench`, in the order `--help` lists them: one list
// for the program and for the Python module, which runs the same commands.
#include "framework/cli/commands.hpp"

namespace hystbench::cli {

std::vector<std::pair<CLI::App*, Action>> add_all_commands(CLI::App& app) {
  std::vector<std::pair<CLI::App*, Action>> commands;
  for (auto add : {add_list_command, add_run_command, add_simulate_command, add_fit_command,
                   add_compare_command, add_diagnose_command, add_discover_command,
                   add_propose_command, add_report_command, add_rank_command,
                   add_control_command, add_svr_command, add_track_command, add_export_command}) {
    auto action = add(app);
    commands.emplace_back(app.get_subcommands({}).back(), action);
  }
  return commands;
}

}  // namespace hystbench::cli
