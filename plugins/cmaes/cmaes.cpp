// CMA-ES with optional IPOP restarts (docs/algorithms.md#cma-es).
//
// Works in normalised coordinates z in [0, 1]^D
// (docs/algorithms.md#normalised-coordinates): the mean starts
// uniformly in the unit box with sigma_0 = 0.3. Each generation's lambda
// offspring are evaluated in one batch at phi(m + sigma y), phi being pycma's
// BoundTransform, so every evaluated point is inside the box by construction
// while the update keeps the untransformed steps.
#include <algorithm>

#include "framework/core/registry.hpp"
#include "framework/evolution/box_transform.hpp"
#include "framework/evolution/cma_state.hpp"
#include "framework/evolution/normalised_space.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

// Doubling stops here so that a long time- or iteration-limited run cannot
// grow the population without bound; restarts go on at this size.
constexpr int max_lambda = 1 << 20;

class CmaEs : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"cmaes",
            "CMA-ES (mu/mu_w, lambda), tutorial defaults, BoundTransform; IPOP restarts by default",
            "N. Hansen, A. Ostermeier, Completely Derandomized Self-Adaptation in Evolution "
            "Strategies, Evolutionary Computation 9(2):159-195, 2001; N. Hansen, The CMA "
            "Evolution Strategy: A Tutorial, arXiv:1604.00772, 2016; A. Auger, N. Hansen, A "
            "Restart CMA Evolution Strategy With Increasing Population Size, CEC 2005, "
            "1769-1776. RECALLED (docs/algorithms.md#cma-es, from the tutorial): default strategy "
            "parameters, update equations (positive weights only, no active CMA), "
            "initialisation m ~ U(0,1)^D with sigma_0 = 0.3, stopping criteria TolFun, TolX, "
            "ConditionCov, NoEffectAxis, NoEffectCoord. SOURCE (pycma code): BoundTransform "
            "box transformation, margins as docs/algorithms.md#boundtransform writes them. RESOLUTION: c_mu and "
            "d_sigma from the tutorial table (not pycma's variants); NoEffectAxis tests axis "
            "g mod D each generation; IPOP population doubling capped at 2^20.",
            {ParamSpec::integer("lambda", nullptr, 2, max_lambda,
                                "offspring per generation (of the first run under IPOP); "
                                "auto = 4 + floor(3 ln D)"),
             ParamSpec::real("sigma0", 0.3, 1e-6, 1.0,
                             "initial step size in normalised coordinates [0,1]^D"),
             ParamSpec::choice("restarts", "ipop", {"none", "ipop"},
                               "none: return when a stopping criterion fires; ipop: restart "
                               "from a new random mean with the population doubled")}};
  }

  explicit CmaEs(const Params& p)
      : lambda_(p.is_auto("lambda") ? 0 : p.integer("lambda")),
        sigma0_(p.real("sigma0")),
        ipop_(p.text("restarts") == "ipop") {}

  void run(EvaluationContext& ctx) override {
    int lambda = lambda_ > 0 ? lambda_ : cma_default_lambda(ctx.dimension());
    while (run_until_stop_criterion(ctx, lambda) && ipop_)
      lambda = std::min(2 * lambda, max_lambda);
  }

 private:
  // One CMA-ES run from a fresh random mean. True when a stopping criterion
  // ended it, false when the budget did.
  bool run_until_stop_criterion(EvaluationContext& ctx, int lambda) const {
    const int n = ctx.dimension();
    const NormalisedSpace space(ctx.bounds());
    const Eigen::VectorXd mean = uniform_population(space.unit(), 1, ctx.rng()).col(0);
    CmaState cma(cma_settings(n, lambda), mean, sigma0_);
    Eigen::VectorXd f;
    while (ctx.next_iteration()) {
      const Eigen::MatrixXd steps = cma.sample_steps(ctx.rng());
      if (space.evaluate(ctx, offspring(cma, steps), f) < lambda) return false;
      cma.update(steps, f);
      if (cma.stop() != CmaStop::None) return true;
    }
    return false;
  }

  // Columns phi(m + sigma y_k): the offspring in the unit box.
  static Eigen::MatrixXd offspring(const CmaState& cma, const Eigen::MatrixXd& steps) {
    Eigen::MatrixXd Z(steps.rows(), steps.cols());
    for (Eigen::Index k = 0; k < steps.cols(); ++k)
      Z.col(k) = unit_box_transform(cma.mean() + cma.sigma() * steps.col(k));
    return Z;
  }

  int lambda_;
  double sigma0_;
  bool ipop_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::CmaEs)
