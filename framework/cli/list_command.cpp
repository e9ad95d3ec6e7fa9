#include <iostream>

#include "framework/cli/commands.hpp"
#include "framework/core/registry.hpp"

namespace hystbench::cli {
namespace {

void print_optimizers() {
  std::cout << "Optimizers (\"algorithms\": [{\"name\": NAME, \"params\": {...}}]):\n";
  for (const auto* info : OptimizerRegistry::instance().all()) {
    std::cout << "\n  " << info->name << " - " << info->summary << "\n";
    for (const auto& p : info->params)
      std::cout << "      " << p.name << ": " << p.describe_range() << "\n          " << p.doc << "\n";
    std::cout << "    Citation: " << info->citation << "\n";
  }
}

void print_problems() {
  std::cout << "\nProblems (\"problem\": {\"type\": NAME, ...}):\n";
  for (const auto* info : ProblemRegistry::instance().all()) {
    std::cout << "\n  " << info->name << " - " << info->summary << "\n      keys:";
    for (const auto& k : info->keys) std::cout << " " << k;
    std::cout << "\n";
  }
}

}  // namespace

Action add_list_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("list", "List optimizers (parameters, defaults, citations) and problems");
  auto load_plugins = add_plugin_option(*cmd);
  return [load_plugins] {
    load_plugins();
    print_optimizers();
    print_problems();
  };
}

}  // namespace hystbench::cli
