// Cost of `propose` (docs/discovery.md#proposing-a-missing-term): the term
// library's columns through the seed chain and the forward regression, on
// 12 000 samples of the planted rate-dependent gain, for libraries of 219
// (degree 3) and 519 (degree 6) terms. The bound: under 10 s on
// 2 cores for a few hundred terms.
#include <benchmark/benchmark.h>

#include "framework/discovery/proposal.hpp"
#include "framework/model/holdout.hpp"
#include "tests/planted_physics.hpp"

namespace {

void BM_Propose(benchmark::State& state) {
  hystbench::planted::System s;
  s.rate_gain = 0.001;
  const double ts = 1e-3;
  const auto m = hystbench::planted::simulate(s, hystbench::planted::multisine(12000, ts), ts);
  hystbench::ModelData data(m, hystbench::SignalScales::of(m));
  hystbench::apply_holdout(data, {});
  const auto model = hystbench::Model::parse("hysteresis,asymmetry,msd,arx");
  Eigen::VectorXd x = model.neutral();
  const auto names = model.parameter_names();
  for (int i = 0; i < model.dimension(); ++i) {
    if (names[i] == "msd.period") x[i] = 0.02;
    if (names[i] == "msd.zeta") x[i] = 0.15;
    if (names[i] == "hysteresis.A") x[i] = 0.1;
  }
  hystbench::ProposeOptions o;
  o.degree = int(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(hystbench::propose_terms(model, x, data, o));
  state.counters["terms"] = double(hystbench::term_library(o.degree).size());
}
BENCHMARK(BM_Propose)->Arg(3)->Arg(6)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
