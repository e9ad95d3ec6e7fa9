#pragma once
// --threads N for the commands whose work runs in OpenMP loops: sets the
// number of worker threads as soon as the option is read. The numbers never
// depend on it (every start, candidate and trial has a seed of its own).
#include <CLI/CLI.hpp>

namespace hystbench::cli {

void add_threads_option(CLI::App* cmd);

}  // namespace hystbench::cli
