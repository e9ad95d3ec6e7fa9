// MEDE, mutation enhanced differential evolution (docs/algorithms.md#mede): every
// individual draws its own F uniformly in [f_min, f_max] and one of three
// mutations (best/1, rand/1, current-to-pbest/1 without archive) with equal
// probability; binomial crossover, MIDPOINT repair, synchronous "<=" selection.
#include <algorithm>
#include <array>

#include "framework/core/registry.hpp"
#include "framework/evolution/de_generation.hpp"
#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/scale_factor.hpp"

namespace hystbench {
namespace {

class Mede : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"mede",
            "[parameter values are a reconstruction] DE with per-individual random F and a random choice of best/1, rand/1 or "
            "current-to-pbest/1 mutation",
            "H. M. Umar, R. Yu, Z. Gao, H. Zhang, Enhancing model estimation accuracy and "
            "convergence rate in hysteresis modeling of MFC actuators using modified differential "
            "evolution algorithm, Extrica (JVE International), article 23309, published 18 May "
            "2023 (title, authors and date checked on extrica.com/article/23309; the DOI "
            "10.21595/vp.2023.23309 is as recorded, not checked). Structure as "
            "in the paper (eqs. 16-19); RESOLUTION: the parameter values (NP, F range, CR, p), "
            "equal strategy probabilities and the absence of an archive are not published and "
            "are this project's choices (docs/algorithms.md#mede).",
            {ParamSpec::integer("np", nullptr, 4, 100000,
                                "population size; auto = 10 x dimension, at least 30"),
             ParamSpec::real("f_min", 0.4, 0.0, 2.0, "lower end of the per-individual F"),
             ParamSpec::real("f_max", 0.9, 0.0, 2.0, "upper end of the per-individual F"),
             ParamSpec::real("cr", 0.9, 0.0, 1.0, "binomial crossover rate CR"),
             ParamSpec::real("p", 0.1, 0.0, 1.0,
                             "p-best fraction for current-to-pbest/1 (top max(2, round(p NP)))"),
             bound_handling_param()}};
  }

  explicit Mede(const Params& p)
      : np_(p.is_auto("np") ? 0 : p.integer("np")),
        f_min_(p.real("f_min")),
        f_max_(p.real("f_max")),
        cr_(p.real("cr")),
        p_(p.real("p")),
        bounds_(bound_handling_from_string(p.text("bounds"))) {}

  void run(EvaluationContext& ctx) override {
    const int np = np_ > 0 ? np_ : std::max(30, 10 * ctx.dimension());
    run_synchronous_de(ctx, np,
                       [&](const DeGeneration& g, Eigen::MatrixXd& U) { make_trials(ctx, g, U); });
  }

 private:
  void make_trials(EvaluationContext& ctx, const DeGeneration& g, Eigen::MatrixXd& U) const {
    static constexpr std::array kStrategies{DeStrategy::Best1, DeStrategy::Rand1,
                                            DeStrategy::CurrentToPbest1};
    const DePopulationView pop{g.X, g.order, pbest_count(p_, static_cast<int>(g.X.cols()))};
    for (int i = 0; i < g.X.cols(); ++i) {
      const double F = uniform_scale_factor(f_min_, f_max_, ctx.rng().uniform());
      const DeStrategy s = kStrategies[ctx.rng().integer(0, kStrategies.size() - 1)];
      const Eigen::VectorXd mutant = de_mutant(s, pop, i, F, ctx.rng());
      U.col(i) = de_trial(g.X.col(i), mutant, cr_, bounds_, ctx);
    }
  }

  int np_;
  double f_min_, f_max_, cr_, p_;
  BoundHandling bounds_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::Mede)
