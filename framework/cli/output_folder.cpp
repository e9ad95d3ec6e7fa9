#include "framework/cli/output_folder.hpp"

#include "framework/core/error.hpp"

namespace hystbench {

namespace fs = std::filesystem;

void check_output_path(const fs::path& dir) {
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InputError("--out " + dir.string() + ": exists and is not a folder; choose another "
                     "folder with --out");
}

void check_output_folder(const fs::path& dir, const std::string& marker, bool replace,
                         const std::string& holds, const std::string& options) {
  check_output_path(dir);
  if (fs::exists(dir / marker) && !replace)
    throw InputError("--out " + dir.string() + ": already holds " + holds + "; " + options +
                     ", or choose another folder with --out");
}

void create_output_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw InputError("--out " + dir.string() + ": cannot create this folder (" + ec.message() +
                     "); choose a folder you can write to with --out");
}

}  // namespace hystbench
