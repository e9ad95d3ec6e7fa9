#pragma once
// The generation loop shared by L-SHADE and jSO (docs/algorithms.md#shade-family):
// success-history memories of F and CR, current-to-pBest(-w)/1 with an
// external archive, binomial crossover, greedy "<=" selection and linear
// population size reduction. The variants differ only in their settings and
// in how they draw F, CR and the p-best weight for each trial.
#include <functional>

#include "framework/core/evaluation_context.hpp"
#include "framework/evolution/bound_handling.hpp"
#include "framework/evolution/current_to_pbest.hpp"
#include "framework/evolution/success_history.hpp"

namespace hystbench {

struct ShadeSettings {
  int np_init = 0;  // N_init (already resolved from the dimension)
  int np_min = 4;   // N_min, reached when the budget is used up
  int memory_size = 6;
  double memory_f = 0.5;
  double memory_cr = 0.5;
  MemoryUpdate memory_update = MemoryUpdate::Replace;
  double archive_rate = 2.6;  // |A| <= round(archive_rate * N)
  // p-best fraction p(tau) = p_start + (p_end - p_start) tau, refreshed after
  // every reduction of the population.
  double p_start = 0.11;
  double p_end = 0.11;
  BoundHandling bounds = BoundHandling::Midpoint;
};

// Control values of one trial vector.
struct TrialControl {
  double CR;
  PbestScales scales;
};

// Draws the control values of one trial from the memories; tau is the
// progress at the start of the generation.
using ControlRule = std::function<TrialControl(const SuccessHistory& memory, double tau, Rng& rng)>;

// Minimises until the context stops. The reduction schedule runs on
// ctx.progress() (nfe / MaxFEs under an evaluation budget).
void run_shade(EvaluationContext& ctx, const ShadeSettings& settings, const ControlRule& control);

}  // namespace hystbench
