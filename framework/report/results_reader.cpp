#include "framework/report/results_reader.hpp"

#include <fstream>
#include <string>

#include "framework/core/error.hpp"
#include "framework/harness/trial_log.hpp"

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

}  // namespace

ResultsFolder read_results_folder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError(dir.string() + ": not a folder; give results folders of `hystbench run`");
  if (!std::filesystem::exists(dir / "summary.json") && std::filesystem::exists(dir / "campaign.json"))
    throw InputError(dir.string() + ": has no summary.json: its run was stopped before the end; "
                     "finish it with `hystbench run EXPERIMENT --out " + dir.string() + " --resume`");
  return {dir, read_summary(dir / "summary.json"), read_trial_log(dir / "trials.jsonl").trials};
}

}  // namespace hystbench
