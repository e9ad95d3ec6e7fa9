#include "framework/core/plugin_loader.hpp"

#include <dlfcn.h>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

std::vector<LoadedPlugin>& plugins() {
  static std::vector<LoadedPlugin> loaded;
  return loaded;
}
// The plugin whose library is being loaded; registrations go to it.
LoadedPlugin* loading = nullptr;

}  // namespace

const std::vector<LoadedPlugin>& loaded_plugins() { return plugins(); }

void detail::note_registration(const std::string& name) {
  if (loading) loading->names.push_back(name);
}

void load_plugin(const std::filesystem::path& library) {
  if (!std::filesystem::exists(library))
    throw InputError("--plugin " + library.string() + ": file not found");
  // A bare file name would make dlopen search the library path instead.
  const std::string path = library.has_parent_path() ? library.string() : "./" + library.string();
  LoadedPlugin plugin{library.string(), {}};
  loading = &plugin;
  // Never unloaded: the registry keeps pointers into the library.
  const bool loaded = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL) != nullptr;
  loading = nullptr;
  if (!loaded) throw InputError("--plugin " + library.string() + ": cannot load: " + dlerror());
  plugins().push_back(std::move(plugin));
}

}  // namespace hystbench
