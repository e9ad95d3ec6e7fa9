// Real-coded genetic algorithm (docs/algorithms.md#ga): the operator set of
// NSGA-II reduced to one objective.
//
// Each generation breeds offspring by tournament selection, crossover
// (probability p_c) and mutation and evaluates them in one batch. Generational
// replacement breeds N - E and keeps them with the E best members of the old
// population; "plus" replacement breeds N, pools them with the parents and
// keeps the best N (the (mu + lambda) reinsertion of pagmo's sga), and by
// default mutates as sga does. The bounded operators keep every child inside
// the box, so no repair is needed.
#include <string>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/evolution/population.hpp"
#include "framework/evolution/real_coded_operators.hpp"

namespace hystbench {
namespace {

class GeneticAlgorithm : public Optimizer {
 public:
  static OptimizerInfo info() {
    return {"ga",
            "Real-coded GA: binary tournament, bounded SBX, bounded polynomial mutation, "
            "generational replacement with 2 elites (sphere-10: ~1e-2 in 50 000 evaluations) "
            "or plus replacement (parents and children pooled, the best N survive)",
            "K. Deb, R. B. Agrawal, Simulated binary crossover for continuous search space, "
            "Complex Systems 9(2):115-148, 1995 (SBX). K. Deb, M. Goyal, A combined genetic "
            "adaptive search (GeneAS) for engineering design, Computer Science and Informatics "
            "26(4):30-45, 1996 (polynomial mutation). K. Deb, A. Pratap, S. Agarwal, "
            "T. Meyarivan, A fast and elitist multiobjective genetic algorithm: NSGA-II, IEEE "
            "TEC 6(2):182-197, 2002 (bounded operators, defaults). L. J. Eshelman, "
            "J. D. Schaffer, Real-coded genetic algorithms and interval-schemata, FOGA 2, 1993 "
            "(BLX-alpha). F. Biscani, D. Izzo, pagmo2, sga in src/algorithms/sga.cpp (the "
            "to-bound polynomial mutation and plus reinsertion). RESOLUTION: the single-objective "
            "configuration is this project's choice (docs/algorithms.md#ga).",
            {ParamSpec::integer("np", 100, 4, 100000,
                                "population size N; each generation breeds N - elites offspring"),
             ParamSpec::choice("replacement", "generational", {"generational", "plus"},
                               "generational: N - elites children and the elites survive; plus: "
                               "N children, the best N of parents and children survive"),
             ParamSpec::integer("elites", 2, 0, 100000,
                                "generational replacement: best members copied unchanged into "
                                "the next generation (< np); plus replacement ignores it"),
             ParamSpec::integer("tournament", 2, 2, 100000,
                                "tournament size (distinct entrants, lowest f wins, ties random)"),
             ParamSpec::choice("crossover", "sbx", real_crossover_names(), "crossover operator"),
             ParamSpec::real("pc", 0.9, 0.0, 1.0, "crossover probability per pair of parents"),
             ParamSpec::real("eta_c", 20.0, 0.0, 1000.0, "SBX distribution index"),
             ParamSpec::real("blx_alpha", 0.5, 0.0, 10.0, "BLX-alpha widening of the interval"),
             ParamSpec::choice("mutation", "auto", mutation_choices(),
                               "mutation operator; auto = polynomial with generational "
                               "replacement, polynomial-to-bound (pagmo's sga) with plus"),
             ParamSpec::real("pm", nullptr, 0.0, 1.0,
                             "mutation probability per variable; auto = 1 / dimension"),
             ParamSpec::real("eta_m", 20.0, 0.0, 1000.0, "polynomial mutation distribution index"),
             ParamSpec::real("sigma_m", 0.1, 0.0, 10.0,
                             "Gaussian mutation standard deviation, as a fraction of the range")}};
  }

  explicit GeneticAlgorithm(const Params& p)
      : np_(p.integer("np")),
        plus_(p.text("replacement") == "plus"),
        elites_(p.integer("elites")),
        tournament_(p.integer("tournament")),
        crossover_(real_crossover_from_string(p.text("crossover"))),
        mutation_(mutation_from(p)),
        pc_(p.real("pc")),
        eta_c_(p.real("eta_c")),
        blx_alpha_(p.real("blx_alpha")),
        pm_(p.is_auto("pm") ? -1.0 : p.real("pm")),
        eta_m_(p.real("eta_m")),
        sigma_m_(p.real("sigma_m")) {
    if (!plus_ && elites_ >= np_)
      throw InputError("ga: elites = " + std::to_string(elites_) + " must be smaller than np = " +
                       std::to_string(np_));
    if (tournament_ > np_)
      throw InputError("ga: tournament = " + std::to_string(tournament_) +
                       " must not exceed np = " + std::to_string(np_));
  }

  void run(EvaluationContext& ctx) override {
    const double pm = pm_ >= 0 ? pm_ : 1.0 / ctx.dimension();
    Eigen::MatrixXd X = uniform_population(ctx.bounds(), np_, ctx.rng());
    Eigen::VectorXd fx;
    if (ctx.evaluate(X, fx) < np_) return;

    Eigen::MatrixXd Y(ctx.dimension(), plus_ ? np_ : np_ - elites_);
    Eigen::VectorXd fy;
    while (ctx.next_iteration()) {
      breed(ctx, X, fx, pm, Y);
      if (ctx.evaluate(Y, fy) < Y.cols()) return;
      survive(X, fx, Y, fy);
    }
  }

 private:
  void breed(EvaluationContext& ctx, const Eigen::MatrixXd& X, const Eigen::VectorXd& fx,
             double pm, Eigen::MatrixXd& Y) const {
    Rng& rng = ctx.rng();
    for (Eigen::Index c = 0; c < Y.cols(); c += 2) {
      const int p1 = tournament(fx, tournament_, rng);
      const int p2 = tournament(fx, tournament_, rng);
      ChildPair kids = rng.uniform() < pc_ ? cross(X.col(p1), X.col(p2), ctx.bounds(), rng)
                                           : ChildPair{X.col(p1), X.col(p2)};
      mutate(kids.first, ctx.bounds(), pm, rng);
      mutate(kids.second, ctx.bounds(), pm, rng);
      Y.col(c) = kids.first;
      // An odd offspring count drops the last second child (the "trim").
      if (c + 1 < Y.cols()) Y.col(c + 1) = kids.second;
    }
  }

  ChildPair cross(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2, const Bounds& bounds,
                  Rng& rng) const {
    switch (crossover_) {
      case RealCrossover::Sbx: return sbx_crossover(y1, y2, bounds, eta_c_, rng);
      case RealCrossover::BlxAlpha: return blx_alpha_crossover(y1, y2, bounds, blx_alpha_, rng);
      case RealCrossover::Arithmetic: return arithmetic_crossover(y1, y2, bounds, rng);
    }
    return {y1, y2};
  }

  void mutate(Eigen::VectorXd& y, const Bounds& bounds, double pm, Rng& rng) const {
    switch (mutation_) {
      case RealMutation::Polynomial: return polynomial_mutation(y, bounds, pm, eta_m_, rng);
      case RealMutation::PolynomialToBound: return polynomial_mutation_to_bound(y, bounds, pm, eta_m_, rng);
      case RealMutation::Gaussian: return gaussian_mutation(y, bounds, pm, sigma_m_, rng);
    }
  }

  static std::vector<std::string> mutation_choices() {
    std::vector<std::string> names{"auto"};
    for (const auto& n : real_mutation_names()) names.push_back(n);
    return names;
  }

  // With plus replacement the GA is pagmo's sga, whose polynomial mutation
  // steps towards a bound by a share of the distance to it; generational
  // replacement keeps the NSGA-II form it was tuned with.
  static RealMutation mutation_from(const Params& p) {
    const std::string name = p.text("mutation");
    if (name != "auto") return real_mutation_from_string(name);
    return p.text("replacement") == "plus" ? RealMutation::PolynomialToBound : RealMutation::Polynomial;
  }

  void survive(Eigen::MatrixXd& X, Eigen::VectorXd& fx, const Eigen::MatrixXd& Y,
               const Eigen::VectorXd& fy) const {
    if (plus_)
      keep_best_of_both(X, fx, Y, fy);
    else
      keep_elites_and_children(X, fx, Y, fy);
  }

  // Next population: the elites of the old one (best first), then offspring.
  void keep_elites_and_children(Eigen::MatrixXd& X, Eigen::VectorXd& fx, const Eigen::MatrixXd& Y,
                                const Eigen::VectorXd& fy) const {
    const auto order = rank_order(fx);
    Eigen::MatrixXd next(X.rows(), X.cols());
    Eigen::VectorXd fnext(fx.size());
    for (int e = 0; e < elites_; ++e) {
      next.col(e) = X.col(order[e]);
      fnext[e] = fx[order[e]];
    }
    next.rightCols(Y.cols()) = Y;
    fnext.tail(fy.size()) = fy;
    X.swap(next);
    fx.swap(fnext);
  }

  // Next population: the N best of parents and children, best first; a tie
  // keeps the parent, which was there first.
  static void keep_best_of_both(Eigen::MatrixXd& X, Eigen::VectorXd& fx, const Eigen::MatrixXd& Y,
                                const Eigen::VectorXd& fy) {
    Eigen::MatrixXd pool(X.rows(), X.cols() + Y.cols());
    pool << X, Y;
    Eigen::VectorXd fpool(fx.size() + fy.size());
    fpool << fx, fy;
    const auto order = rank_order(fpool);
    for (Eigen::Index i = 0; i < X.cols(); ++i) {
      X.col(i) = pool.col(order[i]);
      fx[i] = fpool[order[i]];
    }
  }

  int np_;
  bool plus_;
  int elites_, tournament_;
  RealCrossover crossover_;
  RealMutation mutation_;
  double pc_, eta_c_, blx_alpha_, pm_, eta_m_, sigma_m_;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_OPTIMIZER(hystbench::GeneticAlgorithm)
