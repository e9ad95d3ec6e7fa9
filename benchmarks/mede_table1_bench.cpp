// The MEDE paper's Table 1 experiment end to end (benchmarks/experiments/
// mede_table1.json: DE, GA, DETVSF and MEDE, 30 trials of 100 generations
// each on the bundled data), as `hystbench run` spends its time: every
// trial through the harness, without writing the results folder.
// Argument: threads.
#include <benchmark/benchmark.h>

#include "framework/core/registry.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/experiment.hpp"

namespace {

void BM_MedeTable1Experiment(benchmark::State& state) {
  const auto experiment =
      hystbench::Experiment::load(std::string(HYSTBENCH_SOURCE_DIR) + "/benchmarks/experiments/mede_table1.json");
  const auto problem = hystbench::make_problem(experiment.problem, HYSTBENCH_SOURCE_DIR);
  long evaluations = 0;
  for (auto _ : state) {
    const auto results = hystbench::run_campaign(*problem, experiment, {int(state.range(0))});
    for (const auto& trials : results)
      for (const auto& r : trials) evaluations += r.evaluations;
  }
  state.counters["evaluations_per_second"] =
      benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MedeTable1Experiment)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

}  // namespace
