// Cost of the SVR Hammerstein-like model (docs/svr.md): one blocked
// cross-validation of stage 1 on 2000 regression rows (one evaluation of
// the svr_hyperparameters problem; the seed's PSO makes 600), and the whole
// model's free run over 10 000 samples. Targets: 600 evaluations within 2
// minutes on 2 cores, the free run within 0.5 s.
#include <benchmark/benchmark.h>

#include <cmath>

#include "framework/svr/svr_model.hpp"
#include "framework/svr/svr_validation.hpp"

namespace {

// A play-operator loop on a 1 Hz sine sampled at 2 kHz, 2 periods and a bit.
void loop_record(Eigen::VectorXd& x, Eigen::VectorXd& y, int n) {
  x.resize(n);
  y.resize(n);
  double state = 0.0;
  for (int k = 0; k < n; ++k) {
    x[k] = 75.0 + 75.0 * std::sin(2.0 * M_PI * k / 2000.0);
    state = std::clamp(state, x[k] - 10.0, x[k] + 10.0);
    y[k] = 0.1 * state;
  }
}

void BM_SvrBlockedCv(benchmark::State& state) {
  Eigen::VectorXd x, y;
  loop_record(x, y, 2010);
  Eigen::MatrixXd rows;
  Eigen::VectorXd targets;
  hystbench::SvrHammerstein::regression_rows(x, y, {4, 4}, rows, targets);
  const hystbench::SvrHyperparameters h{state.range(0) * 1e-4, double(state.range(1)), 1.0};
  for (auto _ : state) benchmark::DoNotOptimize(hystbench::blocked_cv_error(rows, targets, h, 5));
}
// (epsilon in 1e-4, C): the box's tight end, and a typical tube.
BENCHMARK(BM_SvrBlockedCv)->Args({10, 10})->Args({10, 1000})->Args({100, 10})->Unit(benchmark::kMillisecond);

void BM_SvrFreeRun(benchmark::State& state) {
  Eigen::VectorXd x, y;
  loop_record(x, y, 2010);
  const auto model = hystbench::SvrHammerstein::fit_stage1(x, y, {4, 4}, {0.001, 10.0, 1.0}, "bench");
  Eigen::VectorXd xt, yt;
  loop_record(xt, yt, 10000);
  for (auto _ : state) benchmark::DoNotOptimize(model.simulate(xt, yt).sum());
  state.counters["support_vectors"] = model.regressor().support_vectors();
}
BENCHMARK(BM_SvrFreeRun)->Unit(benchmark::kMillisecond);

}  // namespace
