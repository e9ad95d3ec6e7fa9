#pragma once
// trials.jsonl: one JSON line per finished trial, appended and flushed at
// once so that a run stopped midway keeps every finished trial.
#include <cstdio>
#include <filesystem>

#include "framework/harness/trial_result.hpp"

namespace hystbench {

class TrialLog {
 public:
  explicit TrialLog(const std::filesystem::path& path);
  ~TrialLog();
  TrialLog(const TrialLog&) = delete;
  TrialLog& operator=(const TrialLog&) = delete;

  void append(const TrialResult& r);

 private:
  std::filesystem::path path_;
  std::FILE* file_;
};

}  // namespace hystbench
