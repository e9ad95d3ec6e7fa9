#pragma once
// Loads an out-of-tree plugin (a shared library built against the installed
// hystbench package). Its HYSTBENCH_OPTIMIZER / HYSTBENCH_PROBLEM objects
// register themselves while the library loads.
#include <filesystem>
#include <string>
#include <vector>

namespace hystbench {

// Throws InputError naming the file and the loader's reason.
void load_plugin(const std::filesystem::path& library);

// The libraries loaded so far, as given, with the names each registered;
// provenance() records them so that a results folder says what made it.
struct LoadedPlugin {
  std::string path;
  std::vector<std::string> names;
};
const std::vector<LoadedPlugin>& loaded_plugins();

namespace detail {
// Called by every registry when an entry is added: while a plugin loads,
// the name is credited to it.
void note_registration(const std::string& name);
}  // namespace detail

}  // namespace hystbench
