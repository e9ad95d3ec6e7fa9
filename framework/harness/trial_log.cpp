#include "framework/harness/trial_log.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

#include "framework/core/error.hpp"

namespace hystbench {

TrialLog::TrialLog(const std::filesystem::path& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "a");
  if (!file_) throw InputError(path.string() + ": cannot open for writing");
}

TrialLog::~TrialLog() {
  if (file_) std::fclose(file_);
}

void TrialLog::append(const TrialResult& r) {
  // One write call per line, then to disk: a crash leaves at most a torn
  // last line, never a lost finished trial.
  const std::string line = r.to_json().dump() + "\n";
  if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
    throw InputError(path_.string() + ": writing failed (disk full?)");
  fsync(fileno(file_));
}

TrialLogContents read_trial_log(const std::filesystem::path& file, bool tolerate_torn_end) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open; is this a results folder of `hystbench run`?");
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const bool ends_in_newline = all.empty() || all.back() == '\n';
  TrialLogContents out;
  std::istringstream lines(all);
  std::string line;
  for (long number = 1; std::getline(lines, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      out.trials.push_back(TrialResult::from_json(nlohmann::json::parse(line)));
    } catch (const std::exception& e) {
      if (tolerate_torn_end && !ends_in_newline && lines.peek() == EOF) {
        out.torn_line = number;
        break;
      }
      throw InputError(file.string() + " line " + std::to_string(number) +
                       ": not a trial record: " + e.what());
    }
  }
  return out;
}

}  // namespace hystbench
