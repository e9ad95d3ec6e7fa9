#include "framework/io/data_path.hpp"

#include "framework/core/error.hpp"

namespace hystbench {

std::filesystem::path resolve_data_path(const std::string& name,
                                        const std::filesystem::path& base_dir,
                                        const std::string& key) {
  const std::filesystem::path given(name);
  if (std::filesystem::exists(given)) return given;
  if (given.is_relative() && !base_dir.empty()) {
    const auto beside = base_dir / given;
    if (std::filesystem::exists(beside)) return beside;
    throw InputError(key + " = \"" + name + "\": file not found (looked in the current folder and in " +
                     base_dir.string() + ")");
  }
  throw InputError(key + " = \"" + name + "\": file not found; check the path (a relative one is "
                   "looked up in the current folder, then beside the experiment file)");
}

}  // namespace hystbench
