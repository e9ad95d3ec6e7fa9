// Cost of one discovery-model fitness evaluation (simulate the effect chain
// and sum the squared error), per sample, for a few model lists.
#include <benchmark/benchmark.h>

#include <cmath>

#include "framework/model/model_problem.hpp"

namespace {

hystbench::ModelData sine_data(Eigen::Index n) {
  hystbench::Measurement m;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, double(n - 1) * 1e-3);
  m.u = (m.t.array() * 2.0 * M_PI * 7.0).sin() * 2.0 + 0.5;
  m.y = m.u;
  m.sample_time = 1e-3;
  return hystbench::ModelData(m, hystbench::SignalScales::of(m));
}

void BM_ModelFitness(benchmark::State& state, const char* model_list) {
  const auto data = sine_data(state.range(0));
  const auto model = hystbench::Model::parse(model_list);
  const hystbench::ModelProblem problem(model, data);
  // Neutral values with every effect switched on a little, so no effect
  // takes its pass-through shortcut.
  Eigen::VectorXd x = model.neutral();
  const auto bounds = model.bounds();
  for (int i = 0; i < model.dimension(); ++i)
    if (x[i] == bounds.lower[i]) x[i] += 0.01 * (bounds.upper[i] - bounds.lower[i]);
    else if (x[i] == 0.0) x[i] = 0.01 * bounds.upper[i];
  for (auto _ : state) benchmark::DoNotOptimize(problem.sse(x));
  state.counters["ns_per_sample"] = benchmark::Counter(
      double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_ModelFitness, gain, "none")->Arg(12000);
BENCHMARK_CAPTURE(BM_ModelFitness, offset, "offset")->Arg(12000);
BENCHMARK_CAPTURE(BM_ModelFitness, seed_chain, "hysteresis,asymmetry,msd,arx")->Arg(12000);

}  // namespace
