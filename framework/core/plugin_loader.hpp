#pragma once
// Loads an out-of-tree plugin (a shared library built against the installed
// hystbench package). Its HYSTBENCH_OPTIMIZER / HYSTBENCH_PROBLEM objects
// register themselves while the library loads.
#include <filesystem>

namespace hystbench {

// Throws InputError naming the file and the loader's reason.
void load_plugin(const std::filesystem::path& library);

}  // namespace hystbench
