// hystbench: benchmark optimizers on hysteresis-model identification.
#include <iostream>
#include <string>

#include "framework/cli/commands.hpp"
#include "framework/cluster/cluster.hpp"
#include "framework/core/error.hpp"

int main(int argc, char** argv) {
  const hystbench::cluster::Session mpi(argc, argv);
  CLI::App app{"hystbench: benchmark optimizers on the identification of hysteresis models "
               "(piezoelectric / MFC actuators) over repeated seeded trials"};
  app.require_subcommand(1);
  // One line, like the errors of the commands themselves.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "hystbench: error: " + std::string(e.what()) + "\n";
  });
#ifdef HYSTBENCH_WITH_MPI
  app.set_version_flag("--version", HYSTBENCH_VERSION " (with MPI)");
#else
  app.set_version_flag("--version", HYSTBENCH_VERSION);
#endif
  const auto commands = hystbench::cli::add_all_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Every rank parsed the same command line; rank 0 alone says so.
    const std::string unknown = hystbench::cli::unknown_command(app, argc, argv);
    if (!unknown.empty()) {
      if (hystbench::cluster::is_coordinator())
        std::cerr << "hystbench: error: " << unknown << "\n";
      return 2;
    }
    const int code = hystbench::cluster::is_coordinator() ? app.exit(e) : e.get_exit_code();
    return code == 0 ? 0 : 2;  // bad command line is bad input
  }
  try {
    for (auto& [command, action] : commands)
      // Under mpirun only `run` is spread over the ranks; rank 0 runs the others.
      if (command->parsed() && (command->get_name() == "run" || hystbench::cluster::is_coordinator()))
        action();
  } catch (const hystbench::cluster::RankStopped& stopped) {
    return stopped.exit_code;
  } catch (const hystbench::InputError& e) {
    std::cerr << "hystbench: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hystbench: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
