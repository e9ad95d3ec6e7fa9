#include "framework/io/truth_file.hpp"

#include <fstream>

namespace hystbench {

nlohmann::json read_truth(const std::filesystem::path& data_file) {
  std::filesystem::path truth = data_file;
  truth.replace_extension(".truth.json");
  std::ifstream in(truth);
  if (!in) return nlohmann::json::object();
  const auto j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() ? j : nlohmann::json::object();
}

}  // namespace hystbench
