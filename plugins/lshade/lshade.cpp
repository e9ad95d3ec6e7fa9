// L-SHADE: SHADE with linear population size reduction
// (docs/algorithms.md#l-shade).
//
// The generation loop lives in framework/evolution/shade_family; this plugin
// supplies L-SHADE's settings and its plain draw of F and CR from a random
// memory slot.
#include <cmath>

#include "framework/core/registry.hpp"
#include "framework/evolution/shade_family.hpp"

namespace hystbench {
namespace {

class Lshade : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"lshade",
            "L-SHADE: success-history adaptive DE, current-to-pbest/1 with archive, linear "
            "population size reduction",
            "R. Tanabe, A. S. Fukunaga, Improving the search performance of SHADE using linear "
            "population size reduction, Proc. IEEE CEC 2014, pp. 1658-1665, "
            "doi:10.1109/CEC.2014.6900380 (SHADE: Tanabe & Fukunaga, CEC 2013, pp. 71-78). "
            "RESOLUTION (docs/algorithms.md#success-history, #l-shade): a TERMINAL CR slot stays terminal as in the "
            "paper; successes with an infinite fitness gain are left out of the memory update; "
            "the archive is trimmed by random deletion; the reduction runs on the budget "
            "fraction used (nfe / MaxFEs, or the iteration or time fraction when there is no "
            "evaluation budget).",
            {ParamSpec::integer("np", nullptr, 4, 100000,
                                "initial population size N_init; auto = round(18 x dimension)"),
             ParamSpec::integer("np_min", 4, 4, 100000,
                                "final population size N_min of the linear reduction"),
             ParamSpec::integer("memory_size", 6, 1, 1000, "number H of memory slots"),
             ParamSpec::real("memory_f", 0.5, 0.0, 1.0, "initial value of the F memories"),
             ParamSpec::real("memory_cr", 0.5, 0.0, 1.0, "initial value of the CR memories"),
             ParamSpec::real("archive_rate", 2.6, 0.0, 100.0,
                             "archive size as a multiple of the current population size"),
             ParamSpec::real("p", 0.11, 0.0, 1.0,
                             "p-best fraction (top max(2, round(p N)) members)"),
             bound_handling_param()}};
  }

  explicit Lshade(const Params& p) : np_(p.is_auto("np") ? 0 : p.integer("np")) {
    s_.np_min = p.integer("np_min");
    s_.memory_size = p.integer("memory_size");
    s_.memory_f = p.real("memory_f");
    s_.memory_cr = p.real("memory_cr");
    s_.memory_update = MemoryUpdate::Replace;
    s_.archive_rate = p.real("archive_rate");
    s_.p_start = s_.p_end = p.real("p");
    s_.bounds = bound_handling_from_string(p.text("bounds"));
  }

  void run(EvaluationContext& ctx) override {
    ShadeSettings s = s_;
    s.np_init = np_ > 0 ? np_ : static_cast<int>(std::lround(18.0 * ctx.dimension()));
    run_shade(ctx, s, draw_control);
  }

 private:
  static TrialControl draw_control(const SuccessHistory& memory, double, Rng& rng) {
    const int slot = static_cast<int>(rng.integer(0, memory.size() - 1));
    const double CR = draw_cr(memory.mu_cr(slot), rng);
    const double F = draw_f(memory.mu_f(slot), rng);
    return {CR, {F, F}};
  }

  int np_;
  ShadeSettings s_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::Lshade)
