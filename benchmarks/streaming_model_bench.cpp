// Cost of running a model sample by sample (StreamingModel) over a 60 s
// record at 1 kHz, the length of one closed-loop run: the seed chain, and
// the Bouc-Wen oscillator with its RK4 sub-steps under the linear hold.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "framework/model/streaming_model.hpp"

namespace {

void BM_StreamingModel(benchmark::State& state, const char* model_list,
                       std::vector<std::pair<std::string, double>> values) {
  const Eigen::Index n = 60000;
  const double ts = 1e-3;
  Eigen::VectorXd u(n);
  for (Eigen::Index k = 0; k < n; ++k) u[k] = std::sin(2.0 * M_PI * 20.61 * ts * double(k));
  const auto model = hystbench::Model::parse(model_list);
  Eigen::VectorXd x = model.neutral();
  const auto names = model.parameter_names();
  for (const auto& [name, value] : values)
    x[std::find(names.begin(), names.end(), name) - names.begin()] = value;
  hystbench::StreamingModel stream(model, x, ts);
  for (auto _ : state) {
    stream.reset();
    double sum = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) sum += stream.step(u[k]);
    if (!std::isfinite(sum)) state.SkipWithError("the stream diverged");
    benchmark::DoNotOptimize(sum);
  }
  state.counters["ns_per_sample"] = benchmark::Counter(
      double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_StreamingModel, seed_chain, "hysteresis,asymmetry,msd,arx",
                  {{"hysteresis.A", 0.3}, {"asymmetry.d2", 0.05}, {"msd.period", 0.02},
                   {"arx.a1", -0.5}, {"arx.b1", 0.1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StreamingModel, feedback_hysteresis, "feedback_hysteresis",
                  {{"feedback_hysteresis.period", 0.04}, {"feedback_hysteresis.zeta", 0.05},
                   {"feedback_hysteresis.alpha", 1.0}, {"feedback_hysteresis.beta_gamma", 0.53},
                   {"feedback_hysteresis.beta_delta", -0.73}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
