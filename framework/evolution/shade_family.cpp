#include "framework/evolution/shade_family.hpp"

#include <vector>

#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/external_archive.hpp"
#include "framework/evolution/population.hpp"
#include "framework/evolution/population_reduction.hpp"

namespace hystbench {
namespace {

class ShadeSearch {
 public:
  ShadeSearch(EvaluationContext& ctx, const ShadeSettings& s, const ControlRule& control)
      : ctx_(ctx),
        s_(s),
        control_(control),
        memory_(s.memory_size, s.memory_f, s.memory_cr, s.memory_update),
        p_(s.p_start) {}

  void run() {
    X_ = uniform_population(ctx_.bounds(), s_.np_init, ctx_.rng());
    if (ctx_.evaluate(X_, fx_) < X_.cols()) return;
    while (ctx_.next_iteration()) {
      make_trials(ctx_.progress());
      const Eigen::Index evaluated = ctx_.evaluate(U_, fu_);
      select(evaluated);
      if (evaluated < U_.cols()) return;
      reduce(ctx_.progress());
    }
  }

 private:
  int np() const { return static_cast<int>(X_.cols()); }

  // Synchronous generation (docs/algorithms.md#synchronous-generations):
  // every trial sees the same population, ranking and archive.
  void make_trials(double tau) {
    const auto order = rank_order(fx_);
    const DePopulationView pop{X_, order, pbest_count(p_, np())};
    U_.resize(X_.rows(), np());
    controls_.clear();
    for (int i = 0; i < np(); ++i) {
      const TrialControl c = control_(memory_, tau, ctx_.rng());
      const Eigen::VectorXd v = current_to_pbest_mutant(pop, archive_, i, c.scales, ctx_.rng());
      U_.col(i) = binomial_crossover(X_.col(i), v, c.CR, ctx_.rng());
      repair(U_.col(i), X_.col(i), ctx_.bounds(), s_.bounds, ctx_.rng());
      controls_.push_back(c);
    }
  }

  // Strict improvements are successes (archived parent, recorded F/CR);
  // ties still replace the parent (docs/algorithms.md#selection).
  void select(Eigen::Index evaluated) {
    SuccessSet successes;
    for (Eigen::Index i = 0; i < evaluated; ++i) {
      if (fu_[i] < fx_[i]) {
        archive_.add(X_.col(i));
        successes.add(controls_[i].scales.F, controls_[i].CR, fx_[i], fu_[i]);
      }
      if (fu_[i] <= fx_[i]) {
        X_.col(i) = U_.col(i);
        fx_[i] = fu_[i];
      }
    }
    archive_.shrink_to(archive_capacity(s_.archive_rate, np()), ctx_.rng());
    memory_.update(successes);
  }

  void reduce(double tau) {
    const int target = linear_population_size(s_.np_init, s_.np_min, tau);
    if (target >= np()) return;
    keep_best(X_, fx_, target);
    archive_.shrink_to(archive_capacity(s_.archive_rate, np()), ctx_.rng());
    p_ = s_.p_start + (s_.p_end - s_.p_start) * tau;
  }

  EvaluationContext& ctx_;
  const ShadeSettings s_;
  const ControlRule control_;
  SuccessHistory memory_;
  ExternalArchive archive_;
  double p_;
  Eigen::MatrixXd X_, U_;
  Eigen::VectorXd fx_, fu_;
  std::vector<TrialControl> controls_;
};

}  // namespace

void run_shade(EvaluationContext& ctx, const ShadeSettings& settings, const ControlRule& control) {
  ShadeSearch(ctx, settings, control).run();
}

}  // namespace hystbench
