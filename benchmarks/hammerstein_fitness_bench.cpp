// Cost of one Hammerstein fitness evaluation per sample, scalar path.
#include <benchmark/benchmark.h>

#include "problems/hammerstein/hammerstein_model.hpp"

namespace {

hystbench::HammersteinParams truth() {
  return {0.25, 2.5e-3, 0.8e-3, 0.2, 0.15, 4e-5, 2.068e-5, 7.276e-4, 1.0, 0.2, 0.09, -1.0, 0.29};
}

void BM_HammersteinScalar(benchmark::State& state) {
  const auto n = state.range(0);
  Eigen::VectorXd u(n), y(n);
  for (Eigen::Index k = 0; k < n; ++k) u[k] = 375 + 625 * std::sin(0.0314 * double(k));
  y.setZero();
  const auto p = truth();
  for (auto _ : state)
    benchmark::DoNotOptimize(hystbench::hammerstein_sse(p, u, y, 1e-3, hystbench::BoucWenForm::Increment));
  state.counters["ns_per_sample_candidate"] =
      benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HammersteinScalar)->Arg(2000)->Arg(10000)->Arg(100000);

}  // namespace
