#include <string>
#include <vector>

#include "framework/cli/commands.hpp"
#include "framework/core/text.hpp"

namespace hystbench::cli {

std::string unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return "no command given (hystbench --help lists the commands)";
  if (argv[1][0] == '-') return "";
  const std::string typed = argv[1];
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  for (const auto& name : names)
    if (name == typed) return "";
  const std::string guess = closest_name(names, typed);
  return "unknown command '" + typed + "'" +
         (guess.empty() ? " " : "; did you mean '" + guess + "'? ") +
         "(hystbench --help lists the commands)";
}

}  // namespace hystbench::cli
