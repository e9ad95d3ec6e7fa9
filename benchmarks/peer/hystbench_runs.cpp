#include "benchmarks/peer/hystbench_runs.hpp"

#include <chrono>

#include "framework/harness/campaign.hpp"

namespace hystbench::peer {

CampaignRun run_hystbench(const Problem& problem, const Experiment& experiment, int threads) {
  CampaignOptions options;
  options.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  const auto results = run_campaign(problem, experiment, options);
  CampaignRun run;
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& algorithm : results) {
    auto& out = run.trials.emplace_back();
    for (const TrialResult& r : algorithm) out.push_back({r.best, r.evaluations, r.wall_seconds});
  }
  return run;
}

}  // namespace hystbench::peer
