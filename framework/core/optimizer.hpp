#pragma once
// An optimizer minimises a problem through the evaluation context. It is
// built from validated parameters and run once per trial; all it needs
// (bounds, RNG, budget state) comes from the context.
#include "framework/core/evaluation_context.hpp"
#include "framework/core/parameters.hpp"

namespace hystbench {

class Optimizer {
 public:
  virtual ~Optimizer() = default;
  // Minimise until ctx says stop (or the method has nothing left to do).
  virtual void run(EvaluationContext& ctx) = 0;
};

}  // namespace hystbench
