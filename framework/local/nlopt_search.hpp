#pragma once
// One NLopt run through the evaluation context (docs/algorithms.md#nlopt).
//
// NLopt's maxeval is not a strict limit, so the wrapper counts the calls it
// makes and stops NLopt (nlopt::forced_stop) once its share of the budget is
// spent; the context counts, records the trace and enforces the whole
// budget as for every other optimizer. NLopt's random generator is seeded
// from the trial's RNG in the calling thread before every run, so NLopt's
// stochastic algorithms reproduce.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/core/evaluation_context.hpp"

namespace hystbench {

// The derivative-free algorithms usable on a box, by NLopt name ("LN_BOBYQA").
const std::vector<std::string>& nlopt_box_algorithms();
// The local ones among them (usable for polishing and as MLSL's local method).
const std::vector<std::string>& nlopt_local_algorithms();

struct NloptSearch {
  std::string algorithm = "LN_BOBYQA";
  std::string local;        // local method of MLSL-type algorithms; "" = NLopt's default
  int population = 0;       // 0 = NLopt's default
  double xtol_rel = 1e-10;  // stopping tolerances of local methods; 0 disables
  double ftol_rel = 1e-12;
  // Initial step of local methods as a fraction of each parameter's range;
  // 0 = NLopt's default (a quarter of the range, less near a bound). From
  // a good start point the default's large first steps land on diverging
  // candidates and BOBYQA's model collapses within ~60 evaluations.
  double initial_step = 0.0;
};

// Minimises from x0 (clamped into the bounds) for at most `max_evaluations`
// evaluations (and never past ctx's budget). Returns NLopt's result name,
// e.g. "XTOL_REACHED" or "FORCED_STOP".
std::string run_nlopt(EvaluationContext& ctx, const NloptSearch& search, Eigen::VectorXd x0,
                      long max_evaluations);

}  // namespace hystbench
