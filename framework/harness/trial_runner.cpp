#include "framework/harness/trial_runner.hpp"

#include <cmath>
#include <exception>

#include "framework/core/registry.hpp"
#include "framework/local/nlopt_search.hpp"

namespace hystbench {
namespace {

void run_with_polish(Optimizer& optimizer, const PolishSpec& polish, long evaluations,
                     EvaluationContext& ctx) {
  const long reserved = std::lround(polish.fraction * double(evaluations));
  ctx.limit_evaluations(evaluations - reserved);
  optimizer.run(ctx);
  ctx.lift_evaluation_limit();
  NloptSearch local;
  local.algorithm = polish.algorithm;
  run_nlopt(ctx, local, ctx.best_point(), ctx.remaining_evaluations());
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
    const auto& info = OptimizerRegistry::instance().find(spec.name, "algorithm");
    auto optimizer = info.create(Params(spec.params));
    if (spec.polish) {
      run_with_polish(*optimizer, *spec.polish, *experiment.budget.evaluations, ctx);
    } else {
      optimizer->run(ctx);
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
