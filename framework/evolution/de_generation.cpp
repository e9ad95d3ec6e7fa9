#include "framework/evolution/de_generation.hpp"

#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/greedy_selection.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {

void run_synchronous_de(EvaluationContext& ctx, int np, const DeTrialBuilder& build,
                        const DeOutcomeObserver& observe) {
  Eigen::MatrixXd X = uniform_population(ctx.bounds(), np, ctx.rng());
  Eigen::VectorXd fx;
  if (ctx.evaluate(X, fx) < np) return;

  Eigen::MatrixXd U(ctx.dimension(), np);
  Eigen::VectorXd fu;
  while (ctx.next_iteration()) {
    const auto order = rank_order(fx);
    build(DeGeneration{X, fx, order}, U);
    // Selection only asks whether a trial beats its target, so a trial may
    // be abandoned once it certainly does not (EvaluationContext).
    const Eigen::Index evaluated = ctx.evaluate_against(U, fx, fu);
    if (observe) observe(fx, fu, evaluated);
    replace_if_not_worse(X, fx, U, fu, evaluated);
  }
}

Eigen::VectorXd de_trial(const Eigen::Ref<const Eigen::VectorXd>& target,
                         const Eigen::VectorXd& mutant, double CR, BoundHandling rule,
                         EvaluationContext& ctx) {
  Eigen::VectorXd trial = binomial_crossover(target, mutant, CR, ctx.rng());
  repair(trial, target, ctx.bounds(), rule, ctx.rng());
  return trial;
}

}  // namespace hystbench
