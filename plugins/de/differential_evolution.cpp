// Classic differential evolution, DE/x/1/bin (docs/algorithms.md#de).
//
// Synchronous generations (docs/algorithms.md#synchronous-generations)
// through the shared DE loop: all trials of a generation are built from the
// same population and evaluated in one batch, then greedy one-to-one
// selection with the "<=" tie rule (docs/algorithms.md#selection).
#include <algorithm>

#include "framework/core/registry.hpp"
#include "framework/evolution/bound_handling.hpp"
#include "framework/evolution/de_generation.hpp"
#include "framework/evolution/de_operators.hpp"

namespace hystbench {
namespace {

class DifferentialEvolution : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"de",
            "Differential evolution DE/x/1/bin with a choice of mutation strategy",
            "R. Storn, K. Price, Differential Evolution - A Simple and Efficient Heuristic for "
            "Global Optimization over Continuous Spaces, J. Global Optimization 11:341-359, "
            "1997. current-to-pbest/1: J. Zhang, A. C. Sanderson, JADE, IEEE TEVC 13(5), 2009.",
            {ParamSpec::integer("np", nullptr, 4, 100000,
                                "population size; auto = 10 x dimension, at least 20"),
             ParamSpec::real("f", 0.5, 0.0, 2.0, "scale factor F of the difference vectors"),
             ParamSpec::real("cr", 0.9, 0.0, 1.0, "binomial crossover rate CR"),
             ParamSpec::choice("strategy", "rand/1", de_strategy_names(), "mutation strategy"),
             ParamSpec::real("p", 0.05, 0.0, 1.0,
                             "p-best fraction for current-to-pbest/1 and pbest/1 (top max(2, round(p NP)))"),
             bound_handling_param()}};
  }

  explicit DifferentialEvolution(const Params& p)
      : np_(p.is_auto("np") ? 0 : p.integer("np")),
        f_(p.real("f")),
        cr_(p.real("cr")),
        p_(p.real("p")),
        strategy_(de_strategy_from_string(p.text("strategy"))),
        bounds_(bound_handling_from_string(p.text("bounds"))) {}

  void run(EvaluationContext& ctx) override {
    const int np = np_ > 0 ? np_ : std::max(20, 10 * ctx.dimension());
    run_synchronous_de(ctx, np, [&](const DeGeneration& g, Eigen::MatrixXd& U) {
      const DePopulationView pop{g.X, g.order, pbest_count(p_, np)};
      for (int i = 0; i < np; ++i)
        U.col(i) = de_trial(g.X.col(i), de_mutant(strategy_, pop, i, f_, ctx.rng()), cr_, bounds_, ctx);
    });
  }

 private:
  int np_;
  double f_, cr_, p_;
  DeStrategy strategy_;
  BoundHandling bounds_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::DifferentialEvolution)
