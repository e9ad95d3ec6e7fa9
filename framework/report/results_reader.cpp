#include "framework/report/results_reader.hpp"

#include <fstream>
#include <string>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

nlohmann::json read_summary(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open; is this a results folder of `hystbench run`?");
  try {
    nlohmann::json j = nlohmann::json::parse(in);
    for (const char* key : {"experiment", "problem", "provenance"})
      if (!j.contains(key)) throw InputError(std::string("missing key \"") + key + "\"");
    return j;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  } catch (const InputError& e) {
    throw InputError(file.string() + ": " + e.what());
  }
}

std::vector<TrialResult> read_trials(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open; is this a results folder of `hystbench run`?");
  std::vector<TrialResult> trials;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      trials.push_back(TrialResult::from_json(nlohmann::json::parse(line)));
    } catch (const std::exception& e) {
      throw InputError(file.string() + " line " + std::to_string(number) +
                       ": not a trial record: " + e.what());
    }
  }
  return trials;
}

}  // namespace

ResultsFolder read_results_folder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError(dir.string() + ": not a folder; give results folders of `hystbench run`");
  return {dir, read_summary(dir / "summary.json"), read_trials(dir / "trials.jsonl")};
}

}  // namespace hystbench
