// Fits the feedback_hysteresis model (Bouc-Wen oscillator) to the estimation
// record of the Bouc-Wen benchmark (Noel & Schoukens 2016) and reports the
// simulation RMSE on the two official test sets, which are used only for
// that report.
//
//   boucwen_feasibility DATA_DIR [--seed N] [--substeps N] [--population N]
//                       [--generations N] [--step-rel R] [--truth]
//
// DATA_DIR holds train_multisine_dynonet.csv, test_multisine.csv and
// test_sinesweep.csv (columns t_s, u_N, y_m). --truth skips the fit and
// simulates the benchmark's published parameters instead.
//
// Fit: differential evolution (rand/1/bin) over the model's default bounds on
// a cheaper objective (first two periods, 5 sub-steps), then LN_BOBYQA and
// LN_NELDERMEAD polish on the whole record at the full sub-step count. The
// objective is the SSE of the normalised output.
#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "framework/io/measurement.hpp"
#include "framework/model/model.hpp"
#include "framework/model/model_data.hpp"

using namespace hystbench;

namespace {

struct Physical {
  double m, c, k, alpha, bg, bd;
};

// gain, log10_fn, zeta, alpha/k, beta*gamma*y_rms, beta*delta*y_rms.
Eigen::VectorXd normalised(const Physical& p, const SignalScales& s) {
  Eigen::VectorXd x(6);
  x << s.u / (p.k * s.y), std::log10(std::sqrt(p.k / p.m) / (2.0 * M_PI)),
      p.c / (2.0 * std::sqrt(p.k * p.m)), p.alpha / p.k, p.bg * s.y, p.bd * s.y;
  return x;
}

Physical physical(const Eigen::VectorXd& x, const SignalScales& s) {
  Physical p;
  p.k = s.u / (x[0] * s.y);
  const double wn = 2.0 * M_PI * std::pow(10.0, x[1]);
  p.m = p.k / (wn * wn);
  p.c = 2.0 * x[2] * std::sqrt(p.k * p.m);
  p.alpha = x[3] * p.k;
  p.bg = x[4] / s.y;
  p.bd = x[5] / s.y;
  return p;
}

struct Objective {
  Objective(const Model* m, const ModelData* d) : model(m), data(d) {}
  const Model* model;
  const ModelData* data;
  long evaluations = 0;
  std::vector<double> best_so_far;  // after each evaluation
  double operator()(const Eigen::VectorXd& x) {
    ++evaluations;
    Eigen::VectorXd y;
    double sse = std::numeric_limits<double>::infinity();
    if (model->simulate(x, *data, y)) sse = (y - data->y).squaredNorm();
    best_so_far.push_back(best_so_far.empty() ? sse : std::min(sse, best_so_far.back()));
    return sse;
  }
  // Evaluations until the best SSE came within `rel` of `target`.
  long evaluations_to(double target, double rel) const {
    for (std::size_t i = 0; i < best_so_far.size(); ++i)
      if (best_so_far[i] <= target * (1.0 + rel)) return long(i + 1);
    return -1;
  }
};

Measurement head(const Measurement& m, Eigen::Index n) {
  Measurement out = m;
  out.t = m.t.head(n);
  out.u = m.u.head(n);
  out.y = m.y.head(n);
  return out;
}

// The test input repeated `periods` times (one period is the steady state).
Measurement repeated(const Measurement& m, int periods) {
  Measurement out = m;
  const Eigen::Index n = m.size();
  out.t.resize(n * periods);
  out.u.resize(n * periods);
  out.y.resize(n * periods);
  for (int p = 0; p < periods; ++p) {
    out.u.segment(p * n, n) = m.u;
    out.y.segment(p * n, n) = m.y;
  }
  for (Eigen::Index i = 0; i < n * periods; ++i) out.t[i] = double(i) * m.sample_time;
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct TestScores {
  double multisine, sweep;
};

TestScores score(const Model& model, const Eigen::VectorXd& x, const SignalScales& scales,
                 const Measurement& multisine, const Measurement& sweep) {
  const int periods = 6;
  const Eigen::Index n = multisine.size();
  ModelData ms(repeated(multisine, periods), scales);
  ModelData sw(sweep, scales);
  Eigen::VectorXd y;
  TestScores s{NAN, NAN};
  if (model.simulate(x, ms, y))
    s.multisine = std::sqrt((y.tail(n) - ms.y.tail(n)).squaredNorm() / double(n)) * scales.y;
  if (model.simulate(x, sw, y))
    s.sweep = std::sqrt((y - sw.y).squaredNorm() / double(sw.size())) * scales.y;
  return s;
}

void print_params(const char* label, const Eigen::VectorXd& x, const SignalScales& scales) {
  const Physical p = physical(x, scales);
  std::printf("%s normalised: gain %.6g log10_fn %.6g zeta %.6g alpha %.6g beta_gamma %.6g beta_delta %.6g\n",
              label, x[0], x[1], x[2], x[3], x[4], x[5]);
  std::printf("%s physical:   m %.5g kg  c %.5g N s/m  k %.6g N/m  alpha %.6g N/m  "
              "beta*gamma %.5g 1/m  beta*delta %.5g 1/m\n",
              label, p.m, p.c, p.k, p.alpha, p.bg, p.bd);
}

// rand/1/bin differential evolution inside the bounds; returns the best point.
Eigen::VectorXd differential_evolution(Objective& f, const Bounds& b, int population,
                                       int generations, std::mt19937_64& rng) {
  const int d = b.dimension();
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, population - 1), dim(0, d - 1);
  std::vector<Eigen::VectorXd> pop(population);
  std::vector<double> cost(population);
  int best = 0;
  for (int i = 0; i < population; ++i) {
    pop[i].resize(d);
    for (int j = 0; j < d; ++j) pop[i][j] = b.lower[j] + unit(rng) * (b.upper[j] - b.lower[j]);
    cost[i] = f(pop[i]);
    if (cost[i] < cost[best]) best = i;
  }
  for (int g = 0; g < generations; ++g) {
    for (int i = 0; i < population; ++i) {
      int r1, r2, r3;
      do r1 = pick(rng); while (r1 == i);
      do r2 = pick(rng); while (r2 == i || r2 == r1);
      do r3 = pick(rng); while (r3 == i || r3 == r1 || r3 == r2);
      const double F = 0.5 + 0.3 * unit(rng), CR = 0.9;
      Eigen::VectorXd trial = pop[i];
      const int jr = dim(rng);
      for (int j = 0; j < d; ++j) {
        if (j != jr && unit(rng) >= CR) continue;
        double v = pop[r1][j] + F * (pop[r2][j] - pop[r3][j]);
        // Bounce back into the box.
        if (v < b.lower[j]) v = b.lower[j] + unit(rng) * (pop[i][j] - b.lower[j]);
        if (v > b.upper[j]) v = b.upper[j] - unit(rng) * (b.upper[j] - pop[i][j]);
        trial[j] = v;
      }
      const double c = f(trial);
      if (c <= cost[i]) {
        pop[i] = trial;
        cost[i] = c;
        if (c < cost[best]) best = i;
      }
    }
    if ((g + 1) % 20 == 0)
      std::printf("  DE generation %d: best SSE %.6g (%ld simulations)\n", g + 1, cost[best],
                  f.evaluations);
  }
  return pop[best];
}

// Initial step of the local methods: `step_rel` of |x_j| (at most 2 % of the
// range, at least 0.1 %), or 2 % of the range when step_rel is 0.
Eigen::VectorXd polish(Objective& f, const Bounds& b, Eigen::VectorXd x, nlopt::algorithm alg,
                       int max_evaluations, double step_rel) {
  const int d = b.dimension();
  nlopt::opt opt(alg, d);
  opt.set_lower_bounds(std::vector<double>(b.lower.data(), b.lower.data() + d));
  opt.set_upper_bounds(std::vector<double>(b.upper.data(), b.upper.data() + d));
  opt.set_xtol_rel(1e-10);
  opt.set_ftol_rel(1e-12);
  opt.set_maxeval(max_evaluations);
  std::vector<double> step(d);
  for (int j = 0; j < d; ++j) {
    const double range = b.upper[j] - b.lower[j];
    step[j] = step_rel > 0.0 ? std::clamp(step_rel * std::abs(x[j]), 1e-3 * range, 0.02 * range)
                             : 0.02 * range;
  }
  opt.set_initial_step(step);
  opt.set_min_objective(
      [](unsigned n, const double* p, double*, void* data) {
        return (*static_cast<Objective*>(data))(Eigen::Map<const Eigen::VectorXd>(p, n));
      },
      &f);
  std::vector<double> xv(x.data(), x.data() + d);
  double fx = 0.0;
  try {
    opt.optimize(xv, fx);
  } catch (const std::exception& e) {
    std::printf("  NLopt stopped: %s\n", e.what());
  }
  return Eigen::Map<Eigen::VectorXd>(xv.data(), d);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: %s DATA_DIR [--seed N] [--substeps N] [--population N] [--generations N] "
                 "[--step-rel R] [--truth]\n",
                 argv[0]);
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  unsigned seed = 1;
  int substeps = 20;
  bool truth_only = false;
  int population = 40, generations = 300;
  double step_rel = 0.0;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seed" && i + 1 < argc) seed = unsigned(std::atoi(argv[++i]));
    else if (a == "--substeps" && i + 1 < argc) substeps = std::atoi(argv[++i]);
    else if (a == "--population" && i + 1 < argc) population = std::atoi(argv[++i]);
    else if (a == "--generations" && i + 1 < argc) generations = std::atoi(argv[++i]);
    else if (a == "--step-rel" && i + 1 < argc) step_rel = std::atof(argv[++i]);
    else if (a == "--truth") truth_only = true;
    else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  const ColumnMap columns{"t_s", "u_N", "y_m"};
  const Measurement train = read_measurement(dir / "train_multisine_dynonet.csv", columns);
  const Measurement test_ms = read_measurement(dir / "test_multisine.csv", columns);
  const Measurement test_sw = read_measurement(dir / "test_sinesweep.csv", columns);
  const SignalScales scales = SignalScales::of(train);
  std::printf("scales: u_rms %.6g N, y_rms %.6g m\n", scales.u, scales.y);

  Model model = Model::parse("feedback_hysteresis");
  model.set_substeps(substeps);
  const Bounds bounds = model.bounds();
  const ModelData data(train, scales);

  const Eigen::VectorXd truth = normalised({2.0, 10.0, 5e4, 5e4, 800.0, -1100.0}, scales);
  print_params("truth", truth, scales);
  std::printf("truth inside the default bounds: %s\n", bounds.contains(truth) ? "yes" : "NO");
  Objective full(&model, &data);
  {
    const auto t0 = std::chrono::steady_clock::now();
    const double sse = full(truth);
    std::printf("truth: estimation RMSE %.4g m (%.1f ms per simulation)\n",
                std::sqrt(sse / double(data.size())) * scales.y, 1e3 * seconds_since(t0));
    const TestScores s = score(model, truth, scales, test_ms, test_sw);
    std::printf("truth: test RMSE multisine %.4g m, sweep %.4g m\n", s.multisine, s.sweep);
  }
  if (truth_only) return 0;

  // Global stage on a cheaper objective: the first two periods at 5 sub-steps.
  Model coarse_model = model;
  coarse_model.set_substeps(5);
  const ModelData coarse_data(head(train, 2 * 8192), scales);
  Objective coarse(&coarse_model, &coarse_data);
  std::mt19937_64 rng(seed);
  auto t0 = std::chrono::steady_clock::now();
  Eigen::VectorXd x = differential_evolution(coarse, bounds, population, generations, rng);
  std::printf("global stage (DE %dx%d, 2 periods, 5 sub-steps): %ld simulations, %.1f s\n",
              population, generations, coarse.evaluations, seconds_since(t0));
  print_params("DE best", x, scales);
  {
    const double sse = full(x);
    std::printf("DE best: estimation RMSE %.4g m\n", std::sqrt(sse / double(data.size())) * scales.y);
  }

  t0 = std::chrono::steady_clock::now();
  full.evaluations = 0;
  full.best_so_far.clear();
  x = polish(full, bounds, x, nlopt::LN_BOBYQA, 2000, step_rel);
  const long bobyqa = full.evaluations;
  x = polish(full, bounds, x, nlopt::LN_NELDERMEAD, 1000, step_rel);
  const double sse = full(x);
  std::printf("local stage: BOBYQA %ld simulations, then Nelder-Mead %ld, %.1f s\n", bobyqa,
              full.evaluations - 1 - bobyqa, seconds_since(t0));
  std::printf("fit: estimation RMSE %.4g m\n", std::sqrt(sse / double(data.size())) * scales.y);
  std::printf("local stage: best SSE within 1e-2 / 1e-4 / 1e-6 of the final after %ld / %ld / %ld "
              "simulations\n",
              full.evaluations_to(sse, 1e-2), full.evaluations_to(sse, 1e-4),
              full.evaluations_to(sse, 1e-6));
  print_params("fit", x, scales);
  const TestScores s = score(model, x, scales, test_ms, test_sw);
  std::printf("fit: test RMSE multisine %.4g m (periodic steady state), sweep %.4g m (from rest)\n",
              s.multisine, s.sweep);
  return 0;
}
