#pragma once
// An optimizer run followed by a local NLopt search from its best point, in
// one evaluation budget and one trace: the optimizer sees `global_share`
// evaluations as its whole budget (its schedules end there), the local
// method gets what remains.
#include <string>

#include "framework/core/evaluation_context.hpp"
#include "framework/core/optimizer.hpp"

namespace hystbench {

void run_polished(Optimizer& optimizer, long global_share, const std::string& local_algorithm,
                  EvaluationContext& ctx);

}  // namespace hystbench
