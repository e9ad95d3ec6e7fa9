#include "framework/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <system_error>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

// On disk before the rename: otherwise a crash just after it can leave an
// empty file under the final name on some file systems.
void sync_to_disk(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, const std::string& content) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string() + ": cannot write this file (check the folder exists and is writable)");
    out << content;
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp, ec);
      throw InputError(path.string() + ": writing failed (disk full?)");
    }
  }
  sync_to_disk(tmp);
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError(path.string() + ": cannot replace the file: " + ec.message());
}

std::vector<std::filesystem::path> write_files_atomic(
    const std::filesystem::path& dir, const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::filesystem::path> out;
  for (const auto& [name, text] : files) {
    write_file_atomic(dir / name, text);
    out.push_back(dir / name);
  }
  return out;
}

}  // namespace hystbench
