#include "framework/report/resume.hpp"

#include <fstream>
#include <set>
#include <utility>

#include "framework/core/error.hpp"
#include "framework/core/rng.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/harness/trial_log.hpp"
#include "framework/report/provenance.hpp"
#include "framework/report/results_merge.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;

// Build identity only: host, date and threads do not change a trial.
nlohmann::json build_identity() {
  const auto p = provenance(1, 0);
  return {{"version", p["version"]}, {"git_commit", p["git_commit"]}};
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON (" + e.what() +
                     "); cannot tell which run the trials belong to: pass --force to start over");
  }
}

// campaign.json, or summary.json in folders written before campaign.json
// existed (those carry no trial slice).
std::pair<fs::path, nlohmann::json> recorded_identity(const fs::path& dir) {
  for (const char* name : {"campaign.json", "summary.json"})
    if (fs::exists(dir / name)) return {dir / name, read_json(dir / name)};
  throw InputError("--resume: " + dir.string() + " holds trials.jsonl but neither campaign.json "
                   "nor summary.json, so it cannot be checked against this experiment; pass "
                   "--force to start over");
}

void require_same_identity(const fs::path& file, const nlohmann::json& recorded,
                           const nlohmann::json& current) {
  nlohmann::json now = current;
  if (!recorded.contains("trial_range")) now.erase("trial_range");
  nlohmann::json was = recorded;
  if (was.contains("provenance")) {
    nlohmann::json build = nlohmann::json::object();
    for (const char* field : {"version", "git_commit"})
      if (was["provenance"].contains(field)) build[field] = was["provenance"][field];
    was["provenance"] = build;
  }
  for (const char* part : {"experiment", "problem", "trial_range", "provenance"}) {
    if (!now.contains(part)) continue;
    const auto d = first_difference(was.value(part, nlohmann::json()), now[part], part);
    if (!d.empty())
      throw InputError("--resume: " + d + " differs between " + file.string() +
                       " and this run: resume with the same experiment file, options (--trials, "
                       "--seed, --trial-range, --columns) and build, or pass --force to start over");
  }
}

void check_trial(const fs::path& log, const Experiment& e, TrialRange range, const TrialResult& r,
                 std::set<std::pair<int, long>>& seen) {
  const std::string where = log.string() + ": trial " + std::to_string(r.trial) + " of " + r.label;
  const auto refuse = [&](const std::string& what) {
    throw InputError(where + ": " + what + "; pass --force to start over");
  };
  if (r.algorithm_index < 0 || std::size_t(r.algorithm_index) >= e.algorithms.size() ||
      e.algorithms[r.algorithm_index].label != r.label)
    refuse("the experiment has no such algorithm at index " + std::to_string(r.algorithm_index));
  if (r.trial < range.first || r.trial >= range.end)
    refuse("outside the trials of this run (" + std::to_string(range.first) + " to " +
           std::to_string(range.end - 1) + ")");
  if (r.seed != trial_seed(e.seed, r.label, static_cast<std::uint64_t>(r.trial)))
    refuse("its seed is not the one this experiment gives it");
  if (!seen.insert({r.algorithm_index, r.trial}).second) refuse("appears twice");
}

// Without the torn line, so that the next append starts a line of its own.
void rewrite_log(const fs::path& log, const std::vector<TrialResult>& trials) {
  std::string lines;
  for (const auto& r : trials) lines += r.to_json().dump() + "\n";
  write_file_atomic(log, lines);
}

}  // namespace

nlohmann::json campaign_identity(const Experiment& experiment, const Problem& problem,
                                 TrialRange range) {
  return {{"experiment", experiment.to_json()},
          {"problem", problem.describe()},
          {"trial_range", std::to_string(range.first) + ":" + std::to_string(range.end)},
          {"provenance", build_identity()}};
}

void write_campaign_identity(const fs::path& dir, const nlohmann::json& identity) {
  write_file_atomic(dir / "campaign.json", identity.dump(2) + "\n");
}

ResumedTrials resume_trials(const fs::path& dir, const nlohmann::json& identity,
                            const Experiment& experiment, TrialRange range) {
  const fs::path log = dir / "trials.jsonl";
  ResumedTrials out;
  if (!fs::exists(log)) return out;
  const auto [file, recorded] = recorded_identity(dir);
  require_same_identity(file, recorded, identity);
  auto contents = read_trial_log(log, /*tolerate_torn_end=*/true);
  std::set<std::pair<int, long>> seen;
  for (const auto& r : contents.trials) check_trial(log, experiment, range, r, seen);
  if (contents.torn_line)
    out.warning = log.string() + " line " + std::to_string(*contents.torn_line) +
                  ": cut short (the run was stopped while writing it); ignored, that trial runs again";
  rewrite_log(log, contents.trials);
  out.finished = std::move(contents.trials);
  return out;
}

}  // namespace hystbench
