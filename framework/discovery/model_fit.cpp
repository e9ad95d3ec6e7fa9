#include "framework/discovery/model_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"
#include "framework/local/nlopt_search.hpp"
#include "framework/model/model_problem.hpp"
#include "framework/stats/descriptive.hpp"

namespace hystbench {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Budget evaluation_budget(long evaluations) {
  Budget b;
  b.evaluations = evaluations;
  return b;
}

// Keeps the best point seen over several contexts.
struct BestSoFar {
  Eigen::VectorXd x;
  double sse = std::numeric_limits<double>::infinity();
  long evaluations = 0;
  std::vector<double> start_sse;

  void take(const EvaluationContext& ctx) {
    evaluations += ctx.evaluations();
    start_sse.push_back(ctx.best_value());
    if (ctx.best_value() < sse) {
      sse = ctx.best_value();
      x = ctx.best_point();
    }
  }
};

// A local search from x0. `fallback` (optional) is evaluated too, so the
// result is never worse than it either.
void polish_from(const Problem& problem, const Eigen::VectorXd& x0, const FitOptions& o,
                 std::uint64_t seed, BestSoFar& best, const Eigen::VectorXd* fallback = nullptr) {
  EvaluationContext ctx(problem, evaluation_budget(o.local_budget(problem.dimension()) + 2), seed);
  if (fallback) ctx.evaluate(problem.bounds().clamp(*fallback));
  ctx.evaluate(problem.bounds().clamp(x0));  // the start counts, so the result is never worse
  NloptSearch local;
  local.algorithm = o.local;
  // Converged well below what any model comparison resolves (a candidate
  // must lower the SSE by a fraction of a percent to count).
  local.ftol_rel = 1e-9;
  local.xtol_rel = 1e-8;
  run_nlopt(ctx, local, ctx.best_point(), ctx.remaining_evaluations());
  best.take(ctx);
}

void report(const FitOptions& o, const std::string& text) {
  if (o.status) o.status(text);
}

// "restart 2 of 3; best SSE so far 12.5; about 40 s left" (normalised SSE).
std::string restart_status(int r, int restarts, double best_sse, double elapsed) {
  std::string s = "restart " + std::to_string(r + 1) + " of " + std::to_string(restarts);
  if (std::isfinite(best_sse)) s += "; best SSE so far " + format_number("%.4g", best_sse);
  if (r > 0) s += "; about " + format_number("%.0f", elapsed / r * (restarts - r)) + " s left";
  return s;
}

// The problem the global stages search: the leading samples of the record
// (when they stand for it, screening_length) and coarse ODE sub-steps
// (FitOptions::screening_*), because they only need to find the right
// basin; every polish uses the whole record at the model's own sub-steps.
struct Coarse {
  Model model;
  ModelData data;
  ModelProblem problem;
  Coarse(const Model& m, const ModelData& d, const FitOptions& o)
      : model(coarse_model(m, o)),
        data(d.head(screening_length(d, o))),
        problem(model, data) {}
  static Model coarse_model(Model m, const FitOptions& o) {
    if (o.screening_substeps > 0) m.set_substeps(o.screening_substeps);
    return m;
  }
};

// The global search for a newly added effect's parameters, the others held
// at x0. It may run on the first part of the record and integrate ODE
// effects coarsely: the polish that follows uses the whole record and the
// model's own sub-steps. Starts from x0 itself, so it is never worse.
FitResult screen_new_effect(const Model& model, const ModelData& data, const Eigen::VectorXd& x0,
                            const std::vector<int>& fresh, const FitOptions& o) {
  const Coarse coarse(model, data, o);
  SubspaceProblem sub(coarse.problem, x0, fresh);
  const long budget = std::max(1000L, o.screening_per_parameter * long(fresh.size()));
  EvaluationContext ctx(sub, evaluation_budget(budget + 1),
                        trial_seed(o.seed, "screen:" + model.text(), 0));
  Eigen::VectorXd z0(fresh.size());
  for (std::size_t i = 0; i < fresh.size(); ++i) z0[i] = x0[fresh[i]];
  ctx.evaluate(z0);
  make_optimizer(o.optimizer, o.optimizer_params, "--optimizer")->run(ctx);
  return {model, sub.expand(ctx.best_point()), ctx.best_value(), ctx.evaluations(), 0.0, {}};
}

// The input's spread, robust to a few spikes: its 0.5 % to 99.5 % quantile
// range.
double input_spread(const Eigen::VectorXd& u) {
  const std::vector<double> v(u.data(), u.data() + u.size());
  return stats::quantile(v, 0.995) - stats::quantile(v, 0.005);
}

}  // namespace

Eigen::Index screening_length(const ModelData& d, const FitOptions& o) {
  const Eigen::Index n = o.screening_samples;
  if (n <= 0 || n >= d.size()) return d.size();
  // On a record whose drive grows (an arrow, a rising step test) the leading
  // samples hold only the small strokes, and a search on them settles in a
  // basin the large ones reject: a Duffing fit of Silverbox's arrow, screened
  // on its first 40 %, polished to twice the error of a fit that never saw
  // the arrow (docs/discovery.md, "`hystbench fit`").
  const double whole = input_spread(d.u);
  return input_spread(d.u.head(n)) >= kScreeningSpread * whole ? n : d.size();
}

long FitOptions::global_budget(int dimension) const {
  return evaluations > 0 ? evaluations : std::max(10000L, 2500L * dimension);
}

long FitOptions::local_budget(int dimension) const {
  return local_evaluations > 0 ? local_evaluations : std::max(1000L, 300L * dimension);
}

void FitOptions::validate() const {
  make_optimizer(optimizer, optimizer_params, "--optimizer");
  const auto& locals = nlopt_local_algorithms();
  if (std::find(locals.begin(), locals.end(), local) == locals.end())
    throw InputError("--local " + local + ": not a local NLopt method; use one of " +
                     join(locals));
  if (restarts < 0) throw InputError("--restarts must be 0 or more");
}

nlohmann::json FitOptions::to_json() const {
  return {{"optimizer", optimizer},        {"optimizer_params", optimizer_params},
          {"evaluations", evaluations},    {"restarts", restarts},
          {"local", local},                {"local_evaluations", local_evaluations},
          {"seed", seed}};
}

FitResult fit_model(const Model& model, const ModelData& data, const FitOptions& o,
                    const Eigen::VectorXd* warm) {
  const auto start = std::chrono::steady_clock::now();
  ModelProblem problem(model, data);
  const Coarse coarse(model, data, o);
  const int dim = problem.dimension();
  BestSoFar best;
  if (warm) {
    report(o, "polishing the warm start");
    polish_from(problem, *warm, o, trial_seed(o.seed, "warm:" + model.text(), 0), best);
  }
  for (int r = 0; r < o.restarts; ++r) {
    report(o, restart_status(r, o.restarts, best.sse, seconds_since(start)));
    const auto seed = trial_seed(o.seed, "fit:" + model.text(), std::uint64_t(r));
    EvaluationContext ctx(coarse.problem, evaluation_budget(o.global_budget(dim)), seed);
    make_optimizer(o.optimizer, o.optimizer_params, "--optimizer")->run(ctx);
    best.evaluations += ctx.evaluations();
    polish_from(problem, ctx.best_point(), o, seed + 1, best);
  }
  if (best.x.size() == 0) best.x = model.neutral(), best.sse = problem.sse(best.x);
  return {model, best.x, best.sse, best.evaluations, seconds_since(start), best.start_sse};
}

FitResult refit_warm(const Model& model, const ModelData& data, const Eigen::VectorXd& x0,
                     const std::vector<int>& fresh, const FitOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  ModelProblem problem(model, data);
  BestSoFar best;
  Eigen::VectorXd from = x0;
  if (!fresh.empty()) {
    const FitResult screened = screen_new_effect(model, data, x0, fresh, o);
    from = screened.x;
    best.evaluations += screened.evaluations;
  }
  // The screening may have judged on part of the record: x0 stays a candidate.
  polish_from(problem, from, o, trial_seed(o.seed, "refit:" + model.text(), 0), best, &x0);
  return {model, best.x, best.sse, best.evaluations, seconds_since(start), best.start_sse};
}

}  // namespace hystbench
