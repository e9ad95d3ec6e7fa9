#pragma once
// The subcommands of `hystbench`. Each registers its options on the app and
// returns the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hystbench::cli {

using Action = std::function<void()>;

// Adds --plugin PATH.so (repeatable) to a subcommand; the returned action
// loads the libraries, to be called before anything looks at the registry.
Action add_plugin_option(CLI::App& command);
// Adds --quiet, which silences the progress display (status_line.hpp).
void add_quiet_option(CLI::App& command);
// Adds --figure-style screen|paper (framework/report/figure_style.hpp).
void add_figure_style_option(CLI::App& command);
// Adds --reference LABEL, the algorithm the statistics table compares
// against (`run` and `report` share it).
void add_reference_option(CLI::App& command, std::string& reference);

// "unknown command 'discovr'; did you mean 'discover'? ..." when the first
// argument is neither an option nor a command of `app`, "no command given ..."
// when there is none, else "". CLI11 would only say that an argument was not
// expected, or that a subcommand is required.
std::string unknown_command(const CLI::App& app, int argc, char** argv);

// Every subcommand below on `app`, with its action, in the order `--help`
// lists them.
std::vector<std::pair<CLI::App*, Action>> add_all_commands(CLI::App& app);

Action add_list_command(CLI::App& app);
Action add_run_command(CLI::App& app);
Action add_simulate_command(CLI::App& app);
Action add_fit_command(CLI::App& app);
Action add_compare_command(CLI::App& app);
Action add_diagnose_command(CLI::App& app);
Action add_discover_command(CLI::App& app);
Action add_propose_command(CLI::App& app);
Action add_report_command(CLI::App& app);
Action add_rank_command(CLI::App& app);
Action add_control_command(CLI::App& app);
Action add_svr_command(CLI::App& app);
Action add_track_command(CLI::App& app);
Action add_export_command(CLI::App& app);

}  // namespace hystbench::cli
