// Jaya (docs/algorithms.md#jaya, Rao 2016): every candidate moves toward the best
// and away from the worst member of the current population and keeps the
// move if it is not worse. No algorithm-specific parameters.
//
// Runs in normalised coordinates z in [0,1]^D
// (docs/algorithms.md#normalised-coordinates), where the |x|
// term of the update is a no-op and negative-valued parameters are not
// biased. All moves of an iteration use the same best and worst and are
// evaluated in one batch.
#include "framework/core/registry.hpp"
#include "framework/evolution/greedy_selection.hpp"
#include "framework/evolution/jaya_operators.hpp"
#include "framework/evolution/normalised_space.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

class Jaya : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"jaya",
            "Jaya: parameter-free moves toward the best and away from the worst, normalised "
            "coordinates",
            "R. Venkata Rao, Jaya: A simple and new optimization algorithm for solving "
            "constrained and unconstrained optimization problems, International Journal of "
            "Industrial Engineering Computations 7(1):19-34, 2016, doi:10.5267/j.ijiec.2015.8.004. "
            "RESOLUTION: fresh r1, r2 per candidate and variable, best/worst fixed per "
            "iteration, CLIP repair, normalised coordinates, NP 50 (docs/algorithms.md#jaya).",
            {ParamSpec::integer("np", 50, 2, 100000, "population size")}};
  }

  explicit Jaya(const Params& p) : np_(p.integer("np")) {}

  void run(EvaluationContext& ctx) override {
    const NormalisedSpace space(ctx.bounds());
    Eigen::MatrixXd Z = uniform_population(space.unit(), np_, ctx.rng());
    Eigen::VectorXd fz;
    if (space.evaluate(ctx, Z, fz) < np_) return;

    Eigen::VectorXd fu;
    while (ctx.next_iteration()) {
      const Eigen::MatrixXd U = jaya_candidates(Z, fz, space.unit(), ctx.rng());
      const Eigen::Index evaluated = space.evaluate(ctx, U, fu);
      replace_if_not_worse(Z, fz, U, fu, evaluated);
      if (evaluated < np_) return;
    }
  }

 private:
  int np_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::Jaya)
