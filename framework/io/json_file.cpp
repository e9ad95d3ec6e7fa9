#include "framework/io/json_file.hpp"

#include <fstream>

#include "framework/core/error.hpp"

namespace hystbench {

nlohmann::json read_json_file(const std::filesystem::path& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open this " + what + "; check the path");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not valid JSON: " + e.what());
  }
}

}  // namespace hystbench
