// Any derivative-free NLopt algorithm on the box (docs/algorithms.md#nlopt), with
// the budget enforced by the wrapper, not by NLopt's approximate maxeval.
#include "framework/core/registry.hpp"
#include "framework/evolution/population.hpp"
#include "framework/local/nlopt_search.hpp"

namespace hystbench {
namespace {

std::vector<std::string> local_choices() {
  std::vector<std::string> c{"default"};
  c.insert(c.end(), nlopt_local_algorithms().begin(), nlopt_local_algorithms().end());
  return c;
}

class NloptOptimizer : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"nlopt",
            "NLopt derivative-free algorithms (DIRECT, CRS2, MLSL, ISRES, ESCH, BOBYQA, ...); "
            "local methods restart from random points until the budget is spent",
            "S. G. Johnson, The NLopt nonlinear-optimization package, version 2.7 "
            "(https://github.com/stevengj/nlopt); each algorithm's own reference is in the "
            "NLopt documentation. Budget enforced by this wrapper; NLopt seeded per trial.",
            {ParamSpec::choice("algorithm", "LN_BOBYQA", nlopt_box_algorithms(),
                               "NLopt algorithm name"),
             ParamSpec::choice("local", "default", local_choices(),
                               "local method of MLSL-type algorithms (required by G_MLSL*)"),
             ParamSpec::integer("population", 0, 0, 1000000,
                                "population of CRS2 / ISRES / MLSL sampling; 0 = NLopt's default"),
             ParamSpec::boolean("restarts", true,
                                "restart local methods from a uniform random point until the "
                                "budget is spent (one restart = one iteration)"),
             ParamSpec::real("xtol_rel", 1e-10, 0.0, 1.0, "relative x tolerance of local methods"),
             ParamSpec::real("ftol_rel", 1e-12, 0.0, 1.0,
                             "relative f tolerance of local methods")}};
  }

  explicit NloptOptimizer(const Params& p) : restarts_(p.boolean("restarts")) {
    search_.algorithm = p.text("algorithm");
    search_.local = p.text("local") == "default" ? "" : p.text("local");
    search_.population = p.integer("population");
    search_.xtol_rel = p.real("xtol_rel");
    search_.ftol_rel = p.real("ftol_rel");
  }

  void run(EvaluationContext& ctx) override {
    const bool local = search_.algorithm.rfind("LN_", 0) == 0;
    while (ctx.next_iteration()) {
      const Eigen::VectorXd start = uniform_population(ctx.bounds(), 1, ctx.rng()).col(0);
      run_nlopt(ctx, search_, start, ctx.remaining_evaluations());
      // A global method has spent what it was given; a second run of a
      // deterministic one would only repeat the first.
      if (!local || !restarts_) return;
    }
  }

 private:
  NloptSearch search_;
  bool restarts_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::NloptOptimizer)
