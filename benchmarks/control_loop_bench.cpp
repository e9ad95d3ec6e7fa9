// Cost of one closed-loop run of the bundled control experiment
// (benchmarks/experiments/avc_beam.json): 60 s at 1 kHz, 32 taps, the
// Bouc-Wen actuator with asymmetry in the control path, the 3-mode beam,
// sensor noise. Target: at most 20 ms per run on one core.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "framework/control/control_run.hpp"

namespace {

void BM_ControlRun(benchmark::State& state, const char* controller) {
  auto x = hystbench::ControlExperiment::load(std::filesystem::path(HYSTBENCH_SOURCE_DIR) /
                                              "benchmarks/experiments/avc_beam.json");
  const hystbench::ControlSetup setup = hystbench::build_control_setup(x);
  hystbench::ControllerEntry entry;
  for (const auto& c : x.controllers)
    if (c.name == controller && !c.in_sweep) {
      entry = c;
      break;
    }
  auto c = entry.make();
  for (auto _ : state) {
    const auto trace = hystbench::run_loop(setup.paths, *setup.estimates[0].stream, *c, setup.loop, 1);
    if (trace.diverged()) state.SkipWithError("the loop diverged");
    benchmark::DoNotOptimize(trace.error.back());
  }
  state.counters["ns_per_sample"] =
      benchmark::Counter(double(setup.loop.samples()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(BM_ControlRun, vss_fxlms, "vss_fxlms")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ControlRun, fxnlms, "fxnlms")->Unit(benchmark::kMillisecond);

}  // namespace
