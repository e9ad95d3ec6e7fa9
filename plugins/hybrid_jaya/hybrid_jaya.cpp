// "Hybrid Jaya" for hysteresis identification
// (docs/algorithms.md#hybrid-jaya), a RECONSTRUCTION: the hybrid cited for
// Bouc-Wen/MFC identification could not be found, so this is the common
// Jaya + DE pattern described there.
//
// Each iteration runs two synchronous phases on the same population, each
// evaluated in one batch with greedy "<=" acceptance: a Jaya phase
// (docs/algorithms.md#jaya, CLIP repair) and a DE/rand/1/bin phase (MIDPOINT
// repair). Everything runs in normalised coordinates z in [0,1]^D
// (docs/algorithms.md#normalised-coordinates).
#include "framework/core/registry.hpp"
#include "framework/evolution/bound_handling.hpp"
#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/greedy_selection.hpp"
#include "framework/evolution/jaya_operators.hpp"
#include "framework/evolution/normalised_space.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

class HybridJaya : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"hybrid_jaya",
            "[RECONSTRUCTION] HJaya (Jaya+DE hybrid): a Jaya phase then a DE/rand/1/bin phase "
            "each iteration, normalised coordinates",
            "RECONSTRUCTION (docs/algorithms.md#hybrid-jaya): the hybrid Jaya cited for Bouc-Wen/MFC "
            "identification could not be located; this Jaya + DE/rand/1/bin hybrid is this "
            "project's rebuild. Components: R. Venkata Rao, Jaya, Int. J. Industrial "
            "Engineering Computations 7(1):19-34, 2016, doi:10.5267/j.ijiec.2015.8.004; "
            "R. Storn, K. Price, Differential Evolution, J. Global Optimization 11:341-359, "
            "1997.",
            {ParamSpec::integer("np", 50, 4, 100000, "population size"),
             ParamSpec::real("f", 0.5, 0.0, 2.0, "DE scale factor F"),
             ParamSpec::real("cr", 0.9, 0.0, 1.0, "DE binomial crossover rate CR")}};
  }

  explicit HybridJaya(const Params& p) : np_(p.integer("np")), f_(p.real("f")), cr_(p.real("cr")) {}

  void run(EvaluationContext& ctx) override {
    const NormalisedSpace space(ctx.bounds());
    Eigen::MatrixXd Z = uniform_population(space.unit(), np_, ctx.rng());
    Eigen::VectorXd fz;
    if (space.evaluate(ctx, Z, fz) < np_) return;

    while (ctx.next_iteration()) {
      if (!phase(ctx, space, Z, fz, jaya_candidates(Z, fz, space.unit(), ctx.rng()))) return;
      if (!phase(ctx, space, Z, fz, de_trials(Z, fz, space.unit(), ctx.rng()))) return;
    }
  }

 private:
  // Evaluates the candidates U and keeps the ones not worse than their
  // parents; false when the budget ran out.
  bool phase(EvaluationContext& ctx, const NormalisedSpace& space, Eigen::MatrixXd& Z,
             Eigen::VectorXd& fz, const Eigen::MatrixXd& U) const {
    Eigen::VectorXd fu;
    const Eigen::Index evaluated = space.evaluate(ctx, U, fu);
    replace_if_not_worse(Z, fz, U, fu, evaluated);
    return evaluated == np_;
  }

  Eigen::MatrixXd de_trials(const Eigen::MatrixXd& Z, const Eigen::VectorXd& fz,
                            const Bounds& unit, Rng& rng) const {
    const auto order = rank_order(fz);
    const DePopulationView pop{Z, order, 1};  // the p-best set is unused by rand/1
    Eigen::MatrixXd U(Z.rows(), Z.cols());
    for (int k = 0; k < np_; ++k) {
      const Eigen::VectorXd mutant = de_mutant(DeStrategy::Rand1, pop, k, f_, rng);
      U.col(k) = binomial_crossover(Z.col(k), mutant, cr_, rng);
      repair(U.col(k), Z.col(k), unit, BoundHandling::Midpoint, rng);
    }
    return U;
  }

  int np_;
  double f_, cr_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::HybridJaya)
