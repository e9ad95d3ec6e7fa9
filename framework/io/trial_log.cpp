#include "framework/io/trial_log.hpp"

#include <unistd.h>

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

}  // namespace hystbench
