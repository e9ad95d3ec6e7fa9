// Cost of one simulation of the feedback_hysteresis model (Bouc-Wen
// oscillator, RK4 with the input between samples by the cubic spline or the
// band-limited kernel) on a record the size of the Bouc-Wen benchmark's
// estimation record (40 960 samples at 750 Hz). Arguments: sub-steps, and
// 0 for the spline, 1 for the band-limited hold, whose kernel an
// oscillator with kinks also asks at arbitrary fractions (tabulated for
// that, band_limited_interpolation.cpp).
#include <benchmark/benchmark.h>

#include <cmath>

#include "framework/model/model.hpp"

namespace {

void BM_FeedbackHysteresisSimulation(benchmark::State& state) {
  const Eigen::Index n = 40960;
  const double ts = 1.0 / 750.0;
  hystbench::ModelData d;
  d.sample_time = ts;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, ts * double(n - 1));
  d.u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < 40; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      d.u[k] += 0.22 * std::sin(2.0 * M_PI * (5.0 + 3.6 * i) * ts * double(k) + 0.37 * i * i);
  d.y = Eigen::VectorXd::Zero(n);
  d.estimation = Eigen::VectorXd::Ones(n);
  hystbench::Model model = hystbench::Model::parse("feedback_hysteresis");
  model.set_substeps(int(state.range(0)));
  model.set_input_hold(state.range(1) == 0 ? hystbench::InputHold::Spline : hystbench::InputHold::Bandlimited);
  // The benchmark's parameters in normalised form.
  Eigen::VectorXd x(6);
  x << 1.51, 1.40, 0.0158, 1.0, 0.53, -0.73;
  Eigen::VectorXd y;
  for (auto _ : state) {
    if (!model.simulate(x, d, y)) state.SkipWithError("simulation failed");
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["ns_per_sample"] =
      benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FeedbackHysteresisSimulation)
    ->Args({5, 0})
    ->Args({20, 0})
    ->Args({5, 1})
    ->Args({20, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace
