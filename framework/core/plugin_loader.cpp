#include "framework/core/plugin_loader.hpp"

#include <dlfcn.h>

#include "framework/core/error.hpp"

namespace hystbench {

void load_plugin(const std::filesystem::path& library) {
  if (!std::filesystem::exists(library))
    throw InputError("--plugin " + library.string() + ": file not found");
  // A bare file name would make dlopen search the library path instead.
  const std::string path = library.has_parent_path() ? library.string() : "./" + library.string();
  // Never unloaded: the registry keeps pointers into the library.
  if (!dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL))
    throw InputError("--plugin " + library.string() + ": cannot load: " + dlerror());
}

}  // namespace hystbench
