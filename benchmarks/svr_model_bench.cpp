// Cost of the SVR Hammerstein-like model (docs/svr.md): one blocked
// cross-validation of stage 1 on 2000 regression rows (one evaluation of
// the svr_hyperparameters problem; the seed's PSO makes 600), and the whole
// model's free run over 10 000 samples, and the whole PSO search of the
// bundled experiment (benchmarks/experiments/svr_piezo.json: swarm 20,
// 600 evaluations) on the simulated actuator's 1 Hz record. Targets: the
// search within 2 minutes on 2 cores, the free run within 0.5 s.
#include <benchmark/benchmark.h>

#include <cmath>

#include <filesystem>

#include "framework/core/registry.hpp"
#include "framework/discovery/model_synthetic_data.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_runner.hpp"
#include "framework/io/json_file.hpp"
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

// The bundled experiment's search on a 1 Hz record made here from the
// actuator, excitation, noise level and seed benchmarks/svr_piezo.sh uses
// (the 1 Hz part alone, so its noise differs in detail from the script's
// record); argument: the rows the search uses.
void BM_SvrPsoSearch(benchmark::State& state) {
  namespace fs = std::filesystem;
  const fs::path source(HYSTBENCH_SOURCE_DIR), spec = source / "benchmarks/experiments/svr_piezo";
  nlohmann::json excitation = hystbench::read_json_file(spec / "train.excitation.json", "excitation");
  excitation["segments"].erase(1);  // the 1 Hz part only
  const auto data = hystbench::make_model_synthetic_data(
      hystbench::Model::parse("hysteresis,asymmetry,msd"), hystbench::read_json_file(spec / "actuator.params.json", "params"),
      excitation, 0.005, 202, "bench", 0.1);
  const fs::path csv = fs::temp_directory_path() / "hystbench_svr_search_bench.csv";
  hystbench::write_measurement(csv, data.data);
  nlohmann::json x = hystbench::read_json_file(source / "benchmarks/experiments/svr_piezo.json", "experiment");
  nlohmann::json problem = x["search"]["problem"];
  problem.update({{"type", "svr_hyperparameters"}, {"data", csv.string()}, {"max_rows", state.range(0)}});
  const auto experiment = hystbench::Experiment::from_json(
      {{"name", "bench"}, {"problem", problem}, {"budget", {{"evaluations", x["search"]["evaluations"]}}},
       {"trials", 1}, {"seed", 1}, {"algorithms", {x["search"]["optimizer"]}}},
      "bench");
  const auto p = hystbench::make_problem(experiment.problem, source);
  for (auto _ : state) {
    const auto r = hystbench::run_trial(*p, experiment, 0, 0, 2);
    state.counters["best_cv_mse"] = r.best;
    state.counters["evaluations"] = double(r.evaluations);
  }
  fs::remove(csv);
}
BENCHMARK(BM_SvrPsoSearch)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
