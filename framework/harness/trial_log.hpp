#pragma once
// trials.jsonl: one JSON line per finished trial, appended and flushed at
// once so that a run stopped midway keeps every finished trial.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

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

struct TrialLogContents {
  std::vector<TrialResult> trials;  // in file order
  std::optional<long> torn_line;    // line number of a last line cut short, when tolerated
};

// Reads every trial of a trials.jsonl. A malformed line is an InputError
// naming the file and line, except, with `tolerate_torn_end`, a last line
// that does not end in a newline: what a crash in the middle of an append
// leaves. That one is dropped and its number returned.
TrialLogContents read_trial_log(const std::filesystem::path& file, bool tolerate_torn_end = false);

}  // namespace hystbench
