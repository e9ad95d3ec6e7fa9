#include "framework/cli/commands.hpp"

namespace hystbench::cli {

void add_reference_option(CLI::App& command, std::string& reference) {
  command.add_option("--reference", reference,
                     "label of the algorithm the rank-sum marks compare against (default: the one "
                     "with the lowest median final fitness)");
}

}  // namespace hystbench::cli
