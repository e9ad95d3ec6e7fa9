#include "framework/io/atomic_file.hpp"

#include <fstream>
#include <system_error>

#include "framework/core/error.hpp"

namespace hystbench {

void write_file_atomic(const std::filesystem::path& path, const std::string& content) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string() + ": cannot write this file (check the folder exists and is writable)");
    out << content;
    out.flush();
    if (!out) throw InputError(path.string() + ": writing failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path.string() + ": cannot replace the file: " + ec.message());
}

}  // namespace hystbench
