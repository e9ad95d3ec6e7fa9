#include "framework/cluster/trial_chunk.hpp"

#include "framework/harness/campaign.hpp"

namespace hystbench::cluster {

void run_chunk(const Problem& problem, const Experiment& experiment, const TrialChunk& chunk,
               int threads, const std::function<void(const TrialResult&)>& on_trial_done) {
  // A one-algorithm experiment: the trial seed depends on the label and the
  // trial index only, so the trials are those of the full experiment.
  Experiment one = experiment;
  one.algorithms = {experiment.algorithms.at(chunk.algorithm)};
  CampaignOptions options;
  options.threads = threads;
  options.trials = chunk.trials;
  options.on_trial_done = [&](const TrialResult& r) {
    TrialResult placed = r;
    placed.algorithm_index = chunk.algorithm;
    on_trial_done(placed);
  };
  run_campaign(problem, one, options);
}

}  // namespace hystbench::cluster
