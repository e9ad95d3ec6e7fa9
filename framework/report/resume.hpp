#pragma once
// What `hystbench run --resume` continues from. Before its first trial, a
// run writes campaign.json into its results folder: the experiment as run,
// the problem, the trial slice and the build. A resumed run must match it
// field for field; it then keeps the folder's finished trials and runs only
// the missing ones, whose seeds depend on nothing but (experiment seed,
// label, trial index), so the result is that of an uninterrupted run.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_range.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench {

// {"experiment", "problem", "trial_range": "FROM:TO", "provenance":
// {"version", "git_commit"}}: what the trials of a results folder are trials of.
nlohmann::json campaign_identity(const Experiment& experiment, const Problem& problem,
                                 TrialRange range);

// Writes dir/campaign.json (atomically).
void write_campaign_identity(const std::filesystem::path& dir, const nlohmann::json& identity);

struct ResumedTrials {
  std::vector<TrialResult> finished;  // kept, in file order
  std::string warning;                // e.g. a torn last line was dropped; empty if none
};

// The finished trials of dir/trials.jsonl, checked against `identity`
// (campaign.json, or summary.json of folders without one): InputError
// naming the first field that differs, a trial outside the run, a seed
// that is not the trial's or a trial found twice. A torn last line (a
// crash mid-append) is dropped with a warning, and trials.jsonl rewritten
// without it so that appending can go on.
ResumedTrials resume_trials(const std::filesystem::path& dir, const nlohmann::json& identity,
                            const Experiment& experiment, TrialRange range);

}  // namespace hystbench
