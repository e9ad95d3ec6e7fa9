#include "framework/local/polished_run.hpp"

#include "framework/local/nlopt_search.hpp"

namespace hystbench {

void run_polished(Optimizer& optimizer, long global_share, const std::string& local_algorithm,
                  EvaluationContext& ctx) {
  ctx.limit_evaluations(global_share);
  optimizer.run(ctx);
  ctx.lift_evaluation_limit();
  NloptSearch local;
  local.algorithm = local_algorithm;
  run_nlopt(ctx, local, ctx.best_point(), ctx.remaining_evaluations());
}

}  // namespace hystbench
