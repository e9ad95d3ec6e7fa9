#include <memory>
#include <string>
#include <vector>

#include "framework/cli/commands.hpp"
#include "framework/core/plugin_loader.hpp"

namespace hystbench::cli {

Action add_plugin_option(CLI::App& command) {
  auto paths = std::make_shared<std::vector<std::string>>();
  command.add_option("--plugin", *paths,
                     "shared-library plugin to load (PATH.so, repeatable; see docs/plugins.md)")
      ->allow_extra_args(false);  // one path per --plugin, so the experiment file is not taken
  return [paths] {
    for (const auto& p : *paths) load_plugin(p);
  };
}

}  // namespace hystbench::cli
