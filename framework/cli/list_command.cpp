#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/core/registry.hpp"
#include "framework/model/effect.hpp"

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

void print_effects() {
  std::cout << "\nEffects (--model NAME,NAME,...; parameters in units of the data normalised by "
               "their RMS):\n";
  for (const auto* info : EffectRegistry::instance().all()) {
    std::cout << "\n  " << info->name << " [" << stage_name(info->stage) << "] - " << info->summary
              << "\n";
    for (const auto& p : info->params)
      std::cout << "      " << p.name << " in [" << p.lower << ", " << p.upper << "], neutral "
                << p.neutral << (p.unit.empty() ? "" : " (" + p.unit + ")") << "\n          "
                << p.doc << "\n";
    if (!info->extends.empty()) std::cout << "    Replaces: " << info->extends << "\n";
    std::cout << "    Signature: " << info->signature << "\n";
    if (!info->statistic.name.empty())
      std::cout << "    Statistic: " << info->statistic.name << "\n";
    if (!info->citation.empty()) std::cout << "    Citation: " << info->citation << "\n";
  }
}

}  // namespace

Action add_list_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "list", "List optimizers (parameters, defaults, citations), problems and model effects");
  auto what = std::make_shared<std::string>("all");
  cmd->add_option("what", *what, "what to list")
      ->check(CLI::IsMember({"all", "optimizers", "problems", "effects"}))
      ->capture_default_str();
  auto load_plugins = add_plugin_option(*cmd);
  return [load_plugins, what] {
    load_plugins();
    if (*what == "all" || *what == "optimizers") print_optimizers();
    if (*what == "all" || *what == "problems") print_problems();
    if (*what == "all" || *what == "effects") print_effects();
  };
}

}  // namespace hystbench::cli
