// What the framework adds to each fitness evaluation (budget, bounds check,
// NaN mapping, best-so-far trace), on a problem that costs almost nothing:
// the sphere in two dimensions, through EvaluationContext::evaluate.
#include <benchmark/benchmark.h>

#include "framework/core/evaluation_context.hpp"
#include "problems/functions/function_problem.hpp"

namespace {

hystbench::Budget unlimited() { return {}; }

// A batch of P candidates per call, as population-based optimizers send.
void BM_OverheadBatch(benchmark::State& state) {
  const hystbench::FunctionProblem sphere("sphere", 2);
  hystbench::EvaluationContext ctx(sphere, unlimited(), 1);
  const Eigen::MatrixXd X = Eigen::MatrixXd::Constant(2, state.range(0), 0.5);
  Eigen::VectorXd f;
  for (auto _ : state) {
    ctx.evaluate(X, f);
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["ns_per_evaluation"] = benchmark::Counter(
      double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_OverheadBatch)->Arg(1)->Arg(32)->Arg(256);

// One candidate per call, as local searches send.
void BM_OverheadSingle(benchmark::State& state) {
  const hystbench::FunctionProblem sphere("sphere", 2);
  hystbench::EvaluationContext ctx(sphere, unlimited(), 1);
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(2, 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(ctx.evaluate(x));
  state.counters["ns_per_evaluation"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_OverheadSingle);

}  // namespace
