#pragma once
// A contiguous slice [first, end) of an experiment's trial indices, so that
// one experiment can be run in pieces (on several machines) and merged later
// with `hystbench report`. Trial k keeps its seed whichever slice runs it.
#include <string>

namespace hystbench {

struct TrialRange {
  long first = 0;
  long end = 0;  // one past the last trial
  long size() const { return end - first; }
};

// Reads "FROM:TO" (0-based, TO exclusive) and checks it against the
// experiment's `trials`. `option` names the option in messages. InputError.
TrialRange parse_trial_range(const std::string& text, long trials, const std::string& option);

}  // namespace hystbench
