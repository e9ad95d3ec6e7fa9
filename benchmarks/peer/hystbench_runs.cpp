#include "benchmarks/peer/hystbench_runs.hpp"

#include <chrono>

#include "framework/harness/campaign.hpp"
#include "framework/harness/trial_runner.hpp"

namespace hystbench::peer {
namespace {

PeerTrial peer_trial(const TrialResult& r) { return {r.best, r.evaluations, r.wall_seconds}; }

}  // namespace

CampaignRun run_hystbench(const Problem& problem, const Experiment& experiment, int threads) {
  CampaignOptions options;
  options.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  const auto results = run_campaign(problem, experiment, options);
  CampaignRun run;
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& algorithm : results) {
    auto& out = run.trials.emplace_back();
    for (const TrialResult& r : algorithm) out.push_back(peer_trial(r));
  }
  return run;
}

PeerTrial run_hystbench_trial(const Problem& problem, const Experiment& experiment, int algorithm,
                              long trial) {
  return peer_trial(run_trial(problem, experiment, algorithm, trial));
}

}  // namespace hystbench::peer
