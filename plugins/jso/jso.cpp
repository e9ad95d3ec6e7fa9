// jSO: L-SHADE with a pinned memory slot, stage-wise CR and F clamps, a
// decreasing p-best fraction and the weighted mutation current-to-pBest-w/1
// (docs/algorithms.md#jso, following the authors' reference code).
//
// The generation loop lives in framework/evolution/shade_family; this plugin
// supplies jSO's settings and its draw of F, CR and the p-best weight.
#include <algorithm>
#include <cmath>

#include "framework/core/registry.hpp"
#include "framework/evolution/shade_family.hpp"

namespace hystbench {
namespace {

// Drawing slot H uses these means, whatever the slot holds.
constexpr double kPinnedMu = 0.9;

class Jso : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"jso",
            "jSO: L-SHADE with weighted current-to-pBest-w/1, tuned memories, decreasing p and "
            "stage-wise F/CR clamps",
            "J. Brest, M. S. Maucec, B. Boskovic, Single objective real-parameter optimization: "
            "Algorithm jSO, Proc. IEEE CEC 2017, pp. 1311-1318, doi:10.1109/CEC.2017.7969456. "
            "Details follow the authors' reference code (docs/algorithms.md#jso). RESOLUTION: p "
            "decreases linearly 0.25 -> 0.125 as in the code (some descriptions write it "
            "increasing); a TERMINAL CR slot is averaged like a number as in the code; successes "
            "with an infinite fitness gain are left out of the memory update; N_init is at least "
            "4; the reduction and the stages run on the budget fraction used (nfe / MaxFEs, or "
            "the iteration or time fraction when there is no evaluation budget).",
            {ParamSpec::integer("np", nullptr, 4, 100000,
                                "initial population size N_init; auto = round(25 sqrt(D) ln(D)), "
                                "at least 4"),
             ParamSpec::integer("np_min", 4, 4, 100000,
                                "final population size N_min of the linear reduction"),
             ParamSpec::integer("memory_size", 5, 2, 1000,
                                "number H of memory slots; the last one is pinned at 0.9"),
             ParamSpec::real("memory_f", 0.3, 0.0, 1.0, "initial value of the F memories"),
             ParamSpec::real("memory_cr", 0.8, 0.0, 1.0, "initial value of the CR memories"),
             ParamSpec::real("archive_rate", 1.0, 0.0, 100.0,
                             "archive size as a multiple of the current population size"),
             ParamSpec::real("p_max", 0.25, 0.0, 1.0, "p-best fraction at the start"),
             ParamSpec::real("p_min", 0.125, 0.0, 1.0,
                             "p-best fraction at the end (linear in the budget fraction)"),
             bound_handling_param()}};
  }

  explicit Jso(const Params& p) : np_(p.is_auto("np") ? 0 : p.integer("np")) {
    s_.np_min = p.integer("np_min");
    s_.memory_size = p.integer("memory_size");
    s_.memory_f = p.real("memory_f");
    s_.memory_cr = p.real("memory_cr");
    s_.memory_update = MemoryUpdate::AverageWithOld;
    s_.archive_rate = p.real("archive_rate");
    s_.p_start = p.real("p_max");
    s_.p_end = p.real("p_min");
    s_.bounds = bound_handling_from_string(p.text("bounds"));
  }

  void run(EvaluationContext& ctx) override {
    ShadeSettings s = s_;
    s.np_init = np_ > 0 ? np_ : default_np(ctx.dimension());
    run_shade(ctx, s, draw_control);
  }

 private:
  static int default_np(int d) {
    return std::max(4, static_cast<int>(std::lround(25.0 * std::sqrt(d) * std::log(d))));
  }

  static TrialControl draw_control(const SuccessHistory& memory, double tau, Rng& rng) {
    const int slot = static_cast<int>(rng.integer(0, memory.size() - 1));
    const bool pinned = slot == memory.size() - 1;
    double CR = draw_cr(pinned ? kPinnedMu : memory.mu_cr(slot), rng);
    if (tau < 0.25)
      CR = std::max(CR, 0.7);
    else if (tau < 0.5)
      CR = std::max(CR, 0.6);
    double F = draw_f(pinned ? kPinnedMu : memory.mu_f(slot), rng);
    if (tau < 0.6) F = std::min(F, 0.7);
    return {CR, {pbest_weight(tau) * F, F, tau < 0.5}};
  }

  // F_w of current-to-pBest-w/1: a weaker pull to the p-best early on, a
  // stronger one late.
  static double pbest_weight(double tau) { return tau < 0.2 ? 0.7 : tau < 0.4 ? 0.8 : 1.2; }

  int np_;
  ShadeSettings s_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::Jso)
