#include "framework/harness/trial_runner.hpp"

#include <cmath>
#include <exception>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/local/levenberg_marquardt.hpp"
#include "framework/local/nlopt_search.hpp"

namespace hystbench {

const LeastSquaresProblem& least_squares_of(const Problem& problem) {
  const auto* lsq = dynamic_cast<const LeastSquaresProblem*>(&problem);
  if (!lsq) throw InputError("problem " + problem.name() + " is not a least-squares problem");
  return *lsq;
}

void check_polish(const Experiment& experiment, const Problem& problem) {
  for (std::size_t i = 0; i < experiment.algorithms.size(); ++i) {
    const auto& polish = experiment.algorithms[i].polish;
    if (!polish || polish->algorithm != PolishSpec::kLevenbergMarquardt) continue;
    if (!dynamic_cast<const LeastSquaresProblem*>(&problem))
      throw InputError("algorithms[" + std::to_string(i) + "].polish.algorithm = \"" + polish->algorithm +
                       "\" needs a least-squares problem (e.g. hammerstein), and " + problem.name() +
                       " is not one; use a local NLopt method such as \"LN_BOBYQA\"");
  }
}

namespace {

// Local searches of a trial polish start with steps of 1 % of each range:
// small enough to stay in the start point's basin (see NloptSearch).
constexpr double kPolishInitialStep = 0.01;

void polish_from_best(const Problem& problem, const PolishSpec& polish, EvaluationContext& ctx) {
  if (polish.algorithm == PolishSpec::kLevenbergMarquardt) {
    run_levenberg_marquardt(ctx, least_squares_of(problem), ctx.best_point(), ctx.remaining_evaluations());
    return;
  }
  NloptSearch local;
  local.algorithm = polish.algorithm;
  local.initial_step = kPolishInitialStep;
  run_nlopt(ctx, local, ctx.best_point(), ctx.remaining_evaluations());
}

// A cycle: a fresh optimizer on (1 - fraction) of the evaluations left, then
// the local search from the best point. Without `repeat` there is one cycle.
void run_with_polish(const Problem& problem, const AlgorithmSpec& spec, EvaluationContext& ctx) {
  const PolishSpec& polish = *spec.polish;
  const auto& info = OptimizerRegistry::instance().find(spec.name, "algorithm");
  // A cycle shorter than this could not even seed a population.
  const long minimum_cycle = 2L * ctx.dimension() + 2;
  do {
    const long left = ctx.remaining_evaluations();
    ctx.limit_evaluations(left - std::lround(polish.fraction * double(left)));
    info.create(Params(spec.params))->run(ctx);
    ctx.lift_evaluation_limit();
    polish_from_best(problem, polish, ctx);
  } while (polish.repeat && !ctx.stopped() && ctx.remaining_evaluations() >= minimum_cycle);
}

}  // namespace

TrialResult run_trial(const Problem& problem, const Experiment& experiment, int algorithm_index,
                      long trial, int evaluation_threads) {
  const AlgorithmSpec& spec = experiment.algorithms[algorithm_index];
  TrialResult r;
  r.label = spec.label;
  r.algorithm_index = algorithm_index;
  r.trial = trial;
  r.seed = trial_seed(experiment.seed, spec.label, static_cast<std::uint64_t>(trial));

  EvaluationContext ctx(problem, experiment.budget, r.seed);
  ctx.set_evaluation_threads(evaluation_threads);
  try {
    if (spec.polish) {
      run_with_polish(problem, spec, ctx);
    } else {
      OptimizerRegistry::instance().find(spec.name, "algorithm").create(Params(spec.params))->run(ctx);
    }
    ctx.finish();
  } catch (const std::exception& e) {
    ctx.fail();
    r.message = e.what();
  }
  // Nothing finite to report is a failure, not a result: it must not sit in
  // the statistics as an ordinary (if bad) fitness.
  if (ctx.stop_reason() != StopReason::Failed && !std::isfinite(ctx.best_value())) {
    ctx.fail();
    r.message = "no candidate had a finite fitness: every evaluation diverged or gave NaN "
                "(check the problem's bounds and data)";
  }
  r.best = ctx.best_value();
  r.evaluations = ctx.evaluations();
  r.iterations = ctx.iterations();
  r.stop = ctx.stop_reason();
  r.best_x.assign(ctx.best_point().begin(), ctx.best_point().end());
  r.trace = ctx.trace();
  r.wall_seconds = ctx.elapsed_seconds();
  return r;
}

}  // namespace hystbench
