// Cost of the robust-control layer on SLICOT's 6-state SB10FD example:
// H∞ synthesis with the γ search, the controller's reduction to 3 states
// by balanced stochastic truncation, and its Tustin discretisation at
// 10 kHz. Target (seed 002's design step): synthesis plus reduction below
// 50 ms.
#include <benchmark/benchmark.h>

#include "framework/robust/hinf_synthesis.hpp"
#include "framework/robust/model_reduction.hpp"
#include "framework/robust/tustin.hpp"
#include "tests/robust/slicot_examples.hpp"

namespace {

using hystbench::robust::StateSpace;

void BM_SynthesisReductionTustin(benchmark::State& state) {
  const StateSpace p = hystbench::robust::examples::sb10fd_plant();
  for (auto _ : state) {
    const auto k = hystbench::robust::hinf_synthesis(p, 2, 2);
    const auto r = hystbench::robust::stochastic_truncation(k.controller, hystbench::robust::TimeDomain::Continuous, 3,
                                                            1e-3);
    benchmark::DoNotOptimize(hystbench::robust::tustin(r.reduced, 1e-4).A.sum());
  }
}
BENCHMARK(BM_SynthesisReductionTustin)->Unit(benchmark::kMillisecond);

}  // namespace
