// hystbench: benchmark optimizers on hysteresis-model identification.
#include <iostream>
#include <utility>
#include <vector>

#include "framework/cli/commands.hpp"
#include "framework/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"hystbench: benchmark optimizers on the identification of hysteresis models "
               "(piezoelectric / MFC actuators) over repeated seeded trials"};
  app.require_subcommand(1);
  app.set_version_flag("--version", HYSTBENCH_VERSION);
  std::vector<std::pair<CLI::App*, hystbench::cli::Action>> commands;
  for (auto add : {hystbench::cli::add_list_command, hystbench::cli::add_run_command,
                   hystbench::cli::add_simulate_command, hystbench::cli::add_fit_command,
                   hystbench::cli::add_compare_command, hystbench::cli::add_diagnose_command,
                   hystbench::cli::add_discover_command,
                   hystbench::cli::add_report_command, hystbench::cli::add_rank_command}) {
    auto action = add(app);
    commands.emplace_back(app.get_subcommands({}).back(), action);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // bad command line is bad input
  }
  try {
    for (auto& [command, action] : commands)
      if (command->parsed()) action();
  } catch (const hystbench::InputError& e) {
    std::cerr << "hystbench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hystbench: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
