// Cost of the Hammerstein fitness per sample and candidate: the scalar
// function on one candidate, then the scalar reference and the batched
// kernel through the real Problem interface (evaluate_with on P candidates,
// N samples, T threads). Like the other benchmarks here, a counter holds
// seconds per item, printed with an SI prefix (470ps = 0.47 ns).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

#include "framework/core/rng.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"
#include "problems/hammerstein/hammerstein_problem.hpp"
#include "problems/hammerstein/recurrence_coefficients.hpp"

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

// The yardstick for the batched kernel: the seed recurrence written as a
// plain loop over eight candidates, state in arrays, for the compiler to
// vectorise on its own (same flags, same coefficients, same operation order,
// so the same SSE bit for bit). The kernel should not be slower than this.
constexpr std::size_t kReferenceLanes = 8;
using Row = std::array<double, kReferenceLanes>;

Row coefficient_row(const std::vector<hystbench::RecurrenceCoefficients>& block,
                    double hystbench::RecurrenceCoefficients::*field) {
  Row row;
  for (std::size_t l = 0; l < row.size(); ++l) row[l] = block[l].*field;
  return row;
}

Row plain_loop_sse(const std::vector<hystbench::RecurrenceCoefficients>& q, const Eigen::VectorXd& u,
                   const Eigen::VectorXd& y) {
  using C = hystbench::RecurrenceCoefficients;
  const Row beta = coefficient_row(q, &C::beta), aL = coefficient_row(q, &C::aL),
            gamma = coefficient_row(q, &C::gamma), d1 = coefficient_row(q, &C::d1),
            d2 = coefficient_row(q, &C::d2), k_h0 = coefficient_row(q, &C::k_h0),
            k_h1 = coefficient_row(q, &C::k_h1), k_h2 = coefficient_row(q, &C::k_h2),
            k_r1 = coefficient_row(q, &C::k_r1), k_r2 = coefficient_row(q, &C::k_r2),
            a = coefficient_row(q, &C::a), b = coefficient_row(q, &C::b),
            c = coefficient_row(q, &C::c), d = coefficient_row(q, &C::d);
  Row h{}, h1_1{}, h1_2{}, r_1{}, r_2{}, r1_1{}, r1_2{}, sse{};
  double u_prev = 0.0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double dr = u[k] - u_prev, abs_dr = std::abs(dr), uk = u[k], yk = y[k];
    u_prev = uk;
    for (std::size_t l = 0; l < kReferenceLanes; ++l) {
      const double hk = (h[l] * (1.0 - beta[l] * abs_dr) + aL[l] * dr) - gamma[l] * dr * std::abs(h[l]);
      const double h1 = d1[l] * uk + d2[l] * uk * uk - hk;
      const double r = (k_h0[l] * h1 + k_h1[l] * h1_1[l] + k_h2[l] * h1_2[l] + k_r2[l] * r_2[l]) + k_r1[l] * r_1[l];
      const double r1 = (a[l] * r_1[l] + b[l] * r_2[l] - d[l] * r1_2[l]) - c[l] * r1_1[l];
      h[l] = hk, h1_2[l] = h1_1[l], h1_1[l] = h1, r_2[l] = r_1[l], r_1[l] = r, r1_2[l] = r1_1[l], r1_1[l] = r1;
      const double e = yk - r1;
      sse[l] += e * e;
    }
  }
  return sse;
}

void BM_HammersteinPlainLoop(benchmark::State& state) {
  const Eigen::Index n = state.range(0), p = state.range(1);
  const hystbench::Measurement m = sine_record(n);
  const Eigen::MatrixXd X = candidates(p);
  std::vector<std::vector<hystbench::RecurrenceCoefficients>> blocks(std::size_t(p) / kReferenceLanes);
  for (Eigen::Index i = 0; i < p; ++i)
    blocks[std::size_t(i) / kReferenceLanes].emplace_back(HammersteinParams::from_vector(X.col(i)), m.sample_time);
  Eigen::VectorXd f(p);
  for (auto _ : state) {
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      const Row sse = plain_loop_sse(blocks[b], m.u, m.y);
      for (std::size_t l = 0; l < kReferenceLanes; ++l) f[Eigen::Index(b * kReferenceLanes + l)] = sse[l];
    }
    benchmark::DoNotOptimize(f.data());
  }
  // A yardstick that computed something else would measure nothing.
  const HammersteinProblem problem(m, BoucWenForm::Increment, HammersteinProblem::default_bounds());
  Eigen::VectorXd kernel(p);
  problem.evaluate_with(X, kernel, hystbench::EvaluationOptions{1});
  if (kernel != f) state.SkipWithError("the plain loop differs from the batched kernel");
  state.counters["ns_per_sample_candidate"] = benchmark::Counter(
      double(n * p), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HammersteinPlainLoop)
    ->ArgNames({"N", "P"})
    ->Args({2000, 64})
    ->Args({10000, 64})
    ->Args({100000, 64})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_TEMPLATE(BM_Hammerstein, ScalarHammerstein)->Name("BM_HammersteinProblemScalar")->Apply(sizes);
BENCHMARK_TEMPLATE(BM_Hammerstein, HammersteinProblem)->Name("BM_HammersteinProblemBatched")->Apply(sizes);

}  // namespace
