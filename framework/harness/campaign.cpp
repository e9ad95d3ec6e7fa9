#include "framework/harness/campaign.hpp"

#include <omp.h>

#include <exception>

#include "framework/harness/thread_split.hpp"
#include "framework/harness/trial_runner.hpp"

namespace hystbench {

std::vector<std::vector<TrialResult>> run_campaign(const Problem& problem,
                                                   const Experiment& experiment,
                                                   const CampaignOptions& options) {
  const int algorithms = static_cast<int>(experiment.algorithms.size());
  const TrialRange range =
      options.trials.size() > 0 ? options.trials : TrialRange{0, experiment.trials};
  const long per_algorithm = range.size();
  const long tasks = algorithms * per_algorithm;
  std::vector<std::vector<TrialResult>> results(algorithms,
                                                std::vector<TrialResult>(per_algorithm));
  std::vector<char> done(tasks, 0);
  for (const TrialResult& r : options.finished) {
    done[r.algorithm_index * per_algorithm + (r.trial - range.first)] = 1;
    results[r.algorithm_index][r.trial - range.first] = r;
  }
  std::exception_ptr callback_error;
  // A resumed run splits its threads by the trials it still has to run.
  const long remaining = tasks - static_cast<long>(options.finished.size());
  const ThreadSplit split = split_threads(remaining, options.threads);

  #pragma omp parallel for schedule(dynamic, 1) num_threads(split.trial_threads)
  for (long task = 0; task < tasks; ++task) {
    if (done[task]) continue;
    const int a = static_cast<int>(task / per_algorithm);
    const long trial = range.first + task % per_algorithm;
    TrialResult r = run_trial(problem, experiment, a, trial, split.evaluation_threads);
    #pragma omp critical(hystbench_trial_done)
    {
      // An exception must not leave an OpenMP region; keep the first.
      try {
        if (options.on_trial_done && !callback_error) options.on_trial_done(r);
      } catch (...) {
        callback_error = std::current_exception();
      }
      results[a][trial - range.first] = std::move(r);
    }
  }
  if (callback_error) std::rethrow_exception(callback_error);
  return results;
}

}  // namespace hystbench
