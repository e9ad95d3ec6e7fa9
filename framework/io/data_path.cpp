#include "framework/io/data_path.hpp"

#include "framework/core/error.hpp"

namespace hystbench {

std::filesystem::path resolve_data_path(const std::string& name,
                                        const std::filesystem::path& base_dir,
                                        const std::string& key) {
  namespace fs = std::filesystem;
  const fs::path given(name);
  if (fs::exists(given)) return given;
  if (!given.is_relative() || base_dir.empty()) throw MissingFileError(key + " = \"" + name + "\": file not found");
  std::error_code ec;
  const fs::path start = fs::absolute(base_dir, ec).lexically_normal();
  for (fs::path dir = start;; dir = dir.parent_path()) {
    if (fs::exists(dir / given)) return (base_dir / dir.lexically_relative(start) / given).lexically_normal();
    if (dir == dir.parent_path()) break;
  }
  throw MissingFileError(key + " = \"" + name + "\": file not found; check the path (a relative one is "
                   "looked up in the current folder, then in " + base_dir.string() +
                   " and the folders above it)");
}

}  // namespace hystbench
