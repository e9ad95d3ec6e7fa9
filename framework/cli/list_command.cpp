#include <iostream>
#include <memory>

#include "framework/cli/commands.hpp"
#include "framework/control/controller.hpp"
#include "framework/control/plant.hpp"
#include "framework/core/registry.hpp"
#include "framework/model/effect.hpp"

namespace hystbench::cli {
namespace {

// Name, summary, parameters and (where the kind has one) citation of every
// entry of a plugin registry.
template <class Registry>
void print_plugins(const std::string& title) {
  std::cout << title;
  for (const auto* info : Registry::instance().all()) {
    std::cout << "\n  " << info->name << " - " << info->summary << "\n";
    for (const auto& p : info->params)
      std::cout << "      " << p.name << ": " << p.describe_range() << "\n          " << p.doc << "\n";
    if constexpr (requires { info->citation; })
      if (!info->citation.empty()) std::cout << "    Citation: " << info->citation << "\n";
  }
}

void print_optimizers() {
  print_plugins<OptimizerRegistry>(
      "Optimizers (\"algorithms\": [{\"name\": NAME, \"params\": {...}}]):\n");
}

void print_problems() {
  print_plugins<ProblemRegistry>("\nProblems (\"problem\": {\"type\": NAME, ...}):\n");
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
      "list", "List optimizers (parameters, defaults, citations), problems, model effects, "
              "controllers and plants");
  auto what = std::make_shared<std::string>("all");
  cmd->add_option("what", *what, "what to list")
      ->check(CLI::IsMember({"all", "optimizers", "problems", "effects", "controllers", "plants"}))
      ->capture_default_str();
  auto load_plugins = add_plugin_option(*cmd);
  return [load_plugins, what] {
    load_plugins();
    if (*what == "all" || *what == "optimizers") print_optimizers();
    if (*what == "all" || *what == "problems") print_problems();
    if (*what == "all" || *what == "effects") print_effects();
    if (*what == "all" || *what == "controllers")
      print_plugins<ControllerRegistry>(
          "\nControllers (hystbench control: \"controllers\": [{\"label\": .., \"name\": NAME, "
          "\"params\": {...}}]):\n");
    if (*what == "all" || *what == "plants")
      print_plugins<PlantRegistry>(
          "\nPlants (hystbench control: \"plant\": {\"type\": NAME, \"params\": {...}}):\n");
  };
}

}  // namespace hystbench::cli
