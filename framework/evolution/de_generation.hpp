#pragma once
// The synchronous DE loop (docs/algorithms.md#de) for variants that differ
// only in how they build trial vectors (DETVSF, DERSF, MEDE, AmFMMDE):
// uniform initialisation, then per generation one batch of NP trials built
// from the same population (docs/algorithms.md#synchronous-generations),
// evaluated in one call, and greedy one-to-one selection with the "<=" tie
// rule (docs/algorithms.md#selection).
#include "framework/core/eigen.hpp"
#include <functional>
#include <vector>

#include "framework/core/evaluation_context.hpp"
#include "framework/evolution/bound_handling.hpp"

namespace hystbench {

// The population at the start of a generation.
struct DeGeneration {
  const Eigen::MatrixXd& X;       // one member per column
  const Eigen::VectorXd& f;       // its fitness
  const std::vector<int>& order;  // ranking, best first
};

// Fills U (dimension x NP) with the generation's trial vectors.
using DeTrialBuilder = std::function<void(const DeGeneration&, Eigen::MatrixXd& U)>;
// Sees the targets' and the trials' fitness of the first `evaluated` trials
// before selection (for success counters). A trial worse than its target
// may carry a value above the target's instead of its exact fitness (early
// abandonment), so compare, do not measure, a losing trial.
using DeOutcomeObserver = std::function<void(
    const Eigen::VectorXd& f_target, const Eigen::VectorXd& f_trial, Eigen::Index evaluated)>;

void run_synchronous_de(EvaluationContext& ctx, int np, const DeTrialBuilder& build,
                        const DeOutcomeObserver& observe = nullptr);

// Trial of one target: binomial crossover with the mutant, then repair of
// the components outside the box against the target
// (docs/algorithms.md#bound-handling).
Eigen::VectorXd de_trial(const Eigen::Ref<const Eigen::VectorXd>& target,
                         const Eigen::VectorXd& mutant, double CR, BoundHandling rule,
                         EvaluationContext& ctx);

}  // namespace hystbench
