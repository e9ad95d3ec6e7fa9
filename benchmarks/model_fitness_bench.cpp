// Cost of one discovery-model fitness evaluation (simulate the effect chain
// and sum the squared error), per sample, for a few model lists; and of a
// batch of candidates of the seed chain one at a time and in blocks.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

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

using Active = std::vector<std::pair<std::string, double>>;

// P candidates near a point where every effect of the model is active.
Eigen::MatrixXd active_candidates(const hystbench::Model& model, const Active& active, Eigen::Index p) {
  Eigen::VectorXd x = model.neutral();
  const auto names = model.parameter_names();
  for (const auto& [name, value] : active)
    x[std::find(names.begin(), names.end(), name) - names.begin()] = value;
  Eigen::MatrixXd X = x.replicate(1, p);
  for (Eigen::Index j = 0; j < p; ++j) X(0, j) *= 1.0 + 1e-3 * double(j);
  return X;
}

const Active kSeedChain = {
    {"hysteresis.A", 0.3}, {"asymmetry.d2", 0.05}, {"msd.period", 0.02}, {"arx.a1", -0.5}, {"arx.b1", 0.1}};
// The Bouc-Wen oscillator in the seed chain's place of msd, with a loop.
const Active kFeedbackChain = {{"hysteresis.A", 0.3},
                               {"asymmetry.d2", 0.05},
                               {"feedback_hysteresis.period", 0.02},
                               {"feedback_hysteresis.alpha", 0.5},
                               {"feedback_hysteresis.beta_gamma", 0.5},
                               {"feedback_hysteresis.beta_delta", -0.2},
                               {"arx.a1", -0.5},
                               {"arx.b1", 0.1}};

// One candidate at a time through ModelProblem::sse (the path of models
// with an effect that has no batched form), or the whole batch through
// evaluate() in blocks of kEffectLanes.
void BM_ModelProblem(benchmark::State& state, bool batched, const char* model_list, const Active* active) {
  const Eigen::Index n = state.range(0), p = state.range(1);
  const int threads = int(state.range(2));
  const auto data = sine_data(n);
  const auto model = hystbench::Model::parse(model_list);
  const hystbench::ModelProblem problem(model, data);
  const Eigen::MatrixXd X = active_candidates(model, *active, p);
  Eigen::VectorXd f(p);
  const int previous = omp_get_max_threads();
  omp_set_num_threads(threads);
  for (auto _ : state) {
    if (batched) {
      problem.evaluate(X, f);
    } else {
#pragma omp parallel for schedule(dynamic)
      for (Eigen::Index j = 0; j < p; ++j) f[j] = problem.sse(X.col(j));
    }
    benchmark::DoNotOptimize(f.data());
  }
  omp_set_num_threads(previous);
  if (!f.allFinite()) state.SkipWithError("a candidate diverged");
  state.counters["ns_per_sample_candidate"] = benchmark::Counter(
      double(n * p), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void model_sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"N", "P", "threads"});
  for (const long threads : {1, 2})
    for (const long n : {2000, 4000, 6000, 8000, 10000}) b->Args({n, 32, threads});
  b->UseRealTime()->Unit(benchmark::kMicrosecond);
}
constexpr const char* kSeed = "hysteresis,asymmetry,msd,arx";
constexpr const char* kFeedback = "hysteresis,asymmetry,feedback_hysteresis,arx";
BENCHMARK_CAPTURE(BM_ModelProblem, scalar, false, kSeed, &kSeedChain)
    ->Name("BM_ModelProblemScalar")
    ->Apply(model_sizes);
BENCHMARK_CAPTURE(BM_ModelProblem, batched, true, kSeed, &kSeedChain)
    ->Name("BM_ModelProblemBatched")
    ->Apply(model_sizes);
// The Bouc-Wen oscillator's chain: blocks run the whole record at once.
void feedback_size(benchmark::internal::Benchmark* b) {
  b->ArgNames({"N", "P", "threads"})->Args({4000, 32, 1})->UseRealTime()->Unit(benchmark::kMillisecond);
}
BENCHMARK_CAPTURE(BM_ModelProblem, feedback_scalar, false, kFeedback, &kFeedbackChain)
    ->Name("BM_FeedbackModelProblemScalar")
    ->Apply(feedback_size);
BENCHMARK_CAPTURE(BM_ModelProblem, feedback_batched, true, kFeedback, &kFeedbackChain)
    ->Name("BM_FeedbackModelProblemBatched")
    ->Apply(feedback_size);

// The global stage of a diagnosis: two candidate fits side by side (an
// outer team of two threads, as a diagnosis runs its candidates), each
// evaluating a batch of the oscillator's chain on the screening problem
// (16 384 samples, 5 sub-steps) in a nested team of its own. OpenMP starts
// the nested teams' threads anew each time, so this is where buffers that
// live per thread, or per block, are paid for again and again.
void BM_FeedbackScreeningSideBySide(benchmark::State& state) {
  const Eigen::Index n = 16384, p = 32;
  const auto data = sine_data(n);
  auto model = hystbench::Model::parse(kFeedback);
  model.set_substeps(5);
  const hystbench::ModelProblem problem(model, data);
  const Eigen::MatrixXd X = active_candidates(model, kFeedbackChain, p);
  Eigen::MatrixXd f(p, 2);
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(2);
  for (auto _ : state) {
#pragma omp parallel for num_threads(2)
    for (int fit = 0; fit < 2; ++fit) problem.evaluate(X, f.col(fit));
    benchmark::DoNotOptimize(f.data());
  }
  omp_set_max_active_levels(levels);
  if (!f.allFinite()) state.SkipWithError("a candidate diverged");
  state.counters["ns_per_sample_candidate"] = benchmark::Counter(
      double(2 * n * p), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FeedbackScreeningSideBySide)->UseRealTime()->Unit(benchmark::kMillisecond);

// Chains of the effects batched last, each run one candidate at a time
// (BM_NAMEModelProblemScalar) and in blocks (BM_NAMEModelProblemBatched) at
// N = 10 000, 32 candidates, one thread.
struct Chain {
  const char* name;
  const char* effects;
  Active active;
};
const std::vector<Chain>& later_batched_chains() {
  static const std::vector<Chain> chains{
      // backlash, saturation and second_mode with the seed chain
      {"Wider", "backlash,hysteresis,asymmetry,saturation,msd,second_mode,arx",
       {{"backlash.r", 0.05}, {"hysteresis.A", 0.3}, {"asymmetry.d2", 0.05}, {"saturation.lambda", 0.2},
        {"msd.period", 0.02}, {"second_mode.participation", 0.1}, {"arx.a1", -0.5}, {"arx.b1", 0.1}}},
      // a delay (each lane its own lag) before it: the slowest hidden-effect cases' model
      {"Delay", "delay,hysteresis,asymmetry,msd",
       {{"delay.d", 2.5}, {"hysteresis.A", 0.3}, {"asymmetry.d2", 0.05}, {"msd.period", 0.02}}}};
  return chains;
}
const bool kLaterChainsRegistered = [] {
  for (const Chain& c : later_batched_chains())
    for (const bool batched : {false, true})
      benchmark::RegisterBenchmark(
          ("BM_" + std::string(c.name) + "ModelProblem" + (batched ? "Batched" : "Scalar")).c_str(),
          BM_ModelProblem, batched, c.effects, &c.active)
          ->ArgNames({"N", "P", "threads"})
          ->Args({10000, 32, 1})
          ->UseRealTime()
          ->Unit(benchmark::kMicrosecond);
  return true;
}();

}  // namespace
