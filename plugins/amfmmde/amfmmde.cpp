// AmFMMDE, adaptive mutation factor and multiple mutation strategy DE
// (docs/algorithms.md#amfmmde): per individual an adaptive F and one of four
// mutations S1 best/1, S2 rand/1, S3 pbest/1, S4 neighbor/1; binomial
// crossover, MIDPOINT repair, synchronous "<=" selection. Only the strategy
// names are published; the F rule, the strategy selection, the reading of
// pbest/1 and the neighbour count are switchable reconstructions.
#include <algorithm>
#include <climits>

#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"
#include "framework/evolution/de_generation.hpp"
#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/scale_factor.hpp"
#include "framework/evolution/strategy_adaptation.hpp"

namespace hystbench {
namespace {

enum class AmfRule { Amf1, Amf2, Amf3 };
const std::vector<std::string> kAmfRules{"amf1", "amf2", "amf3"};
const std::vector<std::string> kSelections{"uniform", "sade"};
const std::vector<std::string> kPbestForms{"current-to-pbest", "pbest-as-base"};
constexpr int kStrategies = 4;  // S1 best/1, S2 rand/1, S3 pbest/1, S4 neighbor/1
constexpr double kSadeEpsilon = 0.01;

const char* const kCitation =
    "The paper that introduced AmFMMDE, for active vibration control of an MFC-actuated "
    "cantilever beam with a non-symmetric Bouc-Wen + ARX Hammerstein model and VSS-FxLMS "
    "(seed paper 000). Cited from its text; its authors could not be confirmed, and the venue "
    "and DOI are as recorded, not checked against the publisher: J. Low Frequency Noise, "
    "Vibration and Active Control (SAGE), 2024, doi:10.1177/14613484241295460. Strategy set "
    "from the paper; DE/neighbor/1 from H. Peng, Z. Guo, "
    "C. Deng, Z. Wu, J. Computational Science 26, 2018, doi:10.1016/j.jocs.2017.07.010. "
    "RECONSTRUCTION (docs/algorithms.md#amfmmde): the adaptive-F rule (AMF-1/2/3), the strategy "
    "selection (uniform or SaDE: Qin, Huang, Suganthan, IEEE TEVC 13(2), 2009, LP generations, "
    "eps 0.01), the neighbour count max(3, round(0.1 NP)) and the reading of DE/pbest/1 "
    "(current-to-pbest by default) are this project's rebuild.";

class Amfmmde : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"amfmmde",
            "[RECONSTRUCTION: F rule, strategy selection, neighbour count] DE with an adaptive F and four mutations (best/1, rand/1, pbest/1, neighbor/1) chosen "
            "per individual",
            kCitation,
            {ParamSpec::integer("np", nullptr, 4, 100000,
                                "population size; auto = 10 x dimension, at least 30"),
             ParamSpec::choice("amf", "amf1", kAmfRules,
                               "F rule: amf1 f_min + (f_max - f_min) U (1 - tau) per individual; "
                               "amf2 f_max - (f_max - f_min) tau; amf3 f0 2^exp(1 - 1/(1 + 1/G_max "
                               "- tau))"),
             ParamSpec::real("f_min", 0.4, 0.0, 2.0, "lower end of F (amf1, amf2)"),
             ParamSpec::real("f_max", 0.9, 0.0, 2.0, "upper end of F (amf1, amf2)"),
             ParamSpec::real("f0", 0.5, 0.0, 2.0, "F at the end of the run (amf3)"),
             ParamSpec::real("cr", 0.9, 0.0, 1.0, "binomial crossover rate CR"),
             ParamSpec::real("p", 0.1, 0.0, 1.0, "p-best fraction (top max(2, round(p NP)))"),
             ParamSpec::choice("pbest_form", "current-to-pbest", kPbestForms,
                               "S3: x_i + F (x_pbest - x_i) + F (x_r1 - x_r2), or "
                               "x_pbest + F (x_r1 - x_r2)"),
             ParamSpec::integer("neighbors", nullptr, 1, 100000,
                                "neighbour count of DE/neighbor/1; auto = max(3, round(0.1 NP)); "
                                "at most NP - 1"),
             ParamSpec::choice("selection", "uniform", kSelections,
                               "strategy choice: uniform 1/4 each, or SaDE success rates"),
             ParamSpec::integer("learning_period", 50, 1, 100000,
                                "SaDE learning period LP in generations (selection = sade)"),
             bound_handling_param()}};
  }

  explicit Amfmmde(const Params& p)
      : np_(p.is_auto("np") ? 0 : p.integer("np")),
        neighbors_(p.is_auto("neighbors") ? 0 : p.integer("neighbors")),
        learning_period_(p.integer("learning_period")),
        amf_(static_cast<AmfRule>(index_of_name(kAmfRules, p.text("amf"), "AMF rule"))),
        sade_(p.text("selection") == "sade"),
        pbest_(p.text("pbest_form") == "current-to-pbest" ? DeStrategy::CurrentToPbest1
                                                          : DeStrategy::Pbest1),
        f_min_(p.real("f_min")),
        f_max_(p.real("f_max")),
        f0_(p.real("f0")),
        cr_(p.real("cr")),
        p_(p.real("p")),
        bounds_(bound_handling_from_string(p.text("bounds"))) {}

  void run(EvaluationContext& ctx) override {
    const int np = np_ > 0 ? np_ : std::max(30, 10 * ctx.dimension());
    RunState state{neighbors_ > 0 ? std::min(neighbors_, np - 1) : default_neighbor_count(np),
                   inverse_gmax(ctx, np),
                   StrategyAdaptation(kStrategies, learning_period_, kSadeEpsilon),
                   std::vector<int>(np)};
    DeOutcomeObserver learn = nullptr;
    if (sade_) {
      learn = [&](const Eigen::VectorXd& fx, const Eigen::VectorXd& fu, Eigen::Index n) {
        for (Eigen::Index i = 0; i < n; ++i) state.selector.record(state.chosen[i], fu[i] < fx[i]);
        state.selector.end_generation();
      };
    }
    run_synchronous_de(
        ctx, np, [&](const DeGeneration& g, Eigen::MatrixXd& U) { make_trials(ctx, g, state, U); },
        learn);
  }

 private:
  // What one run carries from generation to generation.
  struct RunState {
    int neighbors;
    double inverse_gmax;
    StrategyAdaptation selector;
    std::vector<int> chosen;  // strategy of each trial of the current generation
  };

  // 1/G_max with G_max = floor((MaxFEs - NP) / NP)
// (docs/algorithms.md#adaptive-scale-factor); 0 without an
  // evaluation budget, the limit of many generations. Called before any
  // evaluation, so the remaining evaluations are MaxFEs.
  static double inverse_gmax(const EvaluationContext& ctx, int np) {
    const long max_fes = ctx.remaining_evaluations();
    if (max_fes == LONG_MAX) return 0.0;
    return 1.0 / std::max(1L, (max_fes - np) / np);
  }

  double scale_factor(double tau, const RunState& state, Rng& rng) const {
    switch (amf_) {
      case AmfRule::Amf1: return amf1_scale_factor(f_min_, f_max_, rng.uniform(), tau);
      case AmfRule::Amf2: return time_varying_scale_factor(f_min_, f_max_, tau);
      case AmfRule::Amf3: return amf3_scale_factor(f0_, tau, state.inverse_gmax);
    }
    return f_min_;
  }

  Eigen::VectorXd mutant(int s, const DeGeneration& g, const DePopulationView& pop, int i, double F,
                         const RunState& state, Rng& rng) const {
    switch (s) {
      case 0: return de_mutant(DeStrategy::Best1, pop, i, F, rng);
      case 1: return de_mutant(DeStrategy::Rand1, pop, i, F, rng);
      case 2: return de_mutant(pbest_, pop, i, F, rng);
      default: return de_neighbor_mutant(g.X, g.f, i, F, state.neighbors, rng);
    }
  }

  void make_trials(EvaluationContext& ctx, const DeGeneration& g, RunState& state,
                   Eigen::MatrixXd& U) const {
    const double tau = ctx.progress();
    const DePopulationView pop{g.X, g.order, pbest_count(p_, static_cast<int>(g.X.cols()))};
    Rng& rng = ctx.rng();
    for (int i = 0; i < g.X.cols(); ++i) {
      const double F = scale_factor(tau, state, rng);
      const int s =
          sade_ ? state.selector.draw(rng) : static_cast<int>(rng.integer(0, kStrategies - 1));
      state.chosen[i] = s;
      U.col(i) = de_trial(g.X.col(i), mutant(s, g, pop, i, F, state, rng), cr_, bounds_, ctx);
    }
  }

  int np_, neighbors_, learning_period_;
  AmfRule amf_;
  bool sade_;
  DeStrategy pbest_;
  double f_min_, f_max_, f0_, cr_, p_;
  BoundHandling bounds_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::Amfmmde)
