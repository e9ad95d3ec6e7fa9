#pragma once
// The repository's own files, for the tests that hold the docs and the code
// to each other.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace hystbench::test_support {

inline const std::filesystem::path kSourceRoot{HYSTBENCH_SOURCE_DIR};

// The whole file, or "" when it cannot be read.
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace hystbench::test_support
