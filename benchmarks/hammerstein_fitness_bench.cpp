// Cost of the Hammerstein fitness per sample and candidate: the scalar
// function on one candidate, then the scalar reference and the batched
// kernel through the real Problem interface (evaluate_with on P candidates,
// N samples, T threads). Like the other benchmarks here, a counter holds
// seconds per item, printed with an SI prefix (470ps = 0.47 ns).
#include <benchmark/benchmark.h>

#include <cmath>

#include "framework/core/rng.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"

namespace {

using hystbench::BoucWenForm;
using hystbench::HammersteinParams;
using hystbench::HammersteinProblem;

HammersteinParams truth() {
  return {0.25, 2.5e-3, 0.8e-3, 0.2, 0.15, 4e-5, 2.068e-5, 7.276e-4, 1.0, 0.2, 0.09, -1.0, 0.29};
}

// A 5 Hz sine at 1 kHz, measured by the true model: every candidate near
// the truth simulates to the end with finite values.
hystbench::Measurement sine_record(Eigen::Index n) {
  hystbench::Measurement m;
  m.sample_time = 1e-3;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, double(n - 1) * m.sample_time);
  m.u = 375.0 + 625.0 * (m.t.array() * 2.0 * M_PI * 5.0).sin();
  m.y = hystbench::simulate_hammerstein(truth(), m.u, m.sample_time, BoucWenForm::Increment);
  return m;
}

// P stable candidates within +-10 % of the truth, so every lane does work.
Eigen::MatrixXd candidates(Eigen::Index p) {
  hystbench::Rng rng(42);
  const Eigen::VectorXd x0 = truth().to_vector();
  Eigen::MatrixXd X(x0.size(), p);
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < x0.size(); ++j) X(j, i) = x0[j] * rng.uniform(0.9, 1.1);
  return X;
}

// The one-candidate-at-a-time reference behind the same interface.
class ScalarHammerstein : public HammersteinProblem {
 public:
  ScalarHammerstein(hystbench::Measurement m, BoucWenForm form, hystbench::Bounds bounds)
      : HammersteinProblem(m, form, std::move(bounds)), form_(form), ts_(m.sample_time) {}
  void evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f,
                     const hystbench::EvaluationOptions& options) const override {
#pragma omp parallel for schedule(dynamic, 1) num_threads(options.threads) if (options.threads > 1)
    for (Eigen::Index i = 0; i < X.cols(); ++i)
      f[i] = hystbench::hammerstein_sse(HammersteinParams::from_vector(X.col(i)), input(), measured(),
                                        ts_, form_);
  }

 private:
  BoucWenForm form_;
  double ts_;
};

void BM_HammersteinScalar(benchmark::State& state) {
  const auto n = state.range(0);
  Eigen::VectorXd u(n), y(n);
  for (Eigen::Index k = 0; k < n; ++k) u[k] = 375 + 625 * std::sin(0.0314 * double(k));
  y.setZero();
  const auto p = truth();
  for (auto _ : state)
    benchmark::DoNotOptimize(hystbench::hammerstein_sse(p, u, y, 1e-3, BoucWenForm::Increment));
  state.counters["ns_per_sample_candidate"] =
      benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HammersteinScalar)->Arg(2000)->Arg(10000)->Arg(100000);

template <class ProblemType>
void BM_Hammerstein(benchmark::State& state) {
  const Eigen::Index n = state.range(0), p = state.range(1);
  const ProblemType problem(sine_record(n), BoucWenForm::Increment, HammersteinProblem::default_bounds());
  const Eigen::MatrixXd X = candidates(p);
  Eigen::VectorXd f(p);
  const hystbench::EvaluationOptions options{int(state.range(2))};
  for (auto _ : state) {
    problem.evaluate_with(X, f, options);
    benchmark::DoNotOptimize(f.data());
  }
  if (!f.allFinite()) state.SkipWithError("a candidate diverged");
  state.counters["ns_per_sample_candidate"] = benchmark::Counter(
      double(n * p), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"N", "P", "threads"});
  for (const long threads : {1, 2})
    for (const long n : {2000, 10000, 100000})
      for (const long p : {8, 32, 64}) b->Args({n, p, threads});
  b->UseRealTime()->Unit(benchmark::kMicrosecond);
}

BENCHMARK_TEMPLATE(BM_Hammerstein, ScalarHammerstein)->Name("BM_HammersteinProblemScalar")->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Hammerstein, HammersteinProblem)->Name("BM_HammersteinProblemBatched")->Apply(sizes);

}  // namespace
