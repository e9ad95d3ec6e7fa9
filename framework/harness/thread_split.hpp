#pragma once
// How a campaign spends its threads: on trials, or inside each evaluation.
//
// Only one level of parallelism is active at a time, so the cores are never
// oversubscribed and nested OpenMP teams are never needed. With at least as
// many trial tasks as threads, the trials keep every thread busy and each
// evaluation runs on its trial's thread. With fewer (one trial, a short
// --trial-range), the trials run one after another and each evaluation
// shares its candidates between all the threads. Either way every fitness
// value, hence every result, is the same.
namespace hystbench {

struct ThreadSplit {
  int trial_threads = 1;       // trials running at once
  int evaluation_threads = 1;  // threads inside one evaluation (EvaluationOptions::threads)
};

ThreadSplit split_threads(long tasks, int threads);

}  // namespace hystbench
