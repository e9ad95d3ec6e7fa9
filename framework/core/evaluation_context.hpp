#pragma once
// The framework's side of a trial: every fitness evaluation goes through it.
//
// It counts evaluations, enforces the budget, keeps the best point and the
// best-so-far trace, maps NaN/Inf fitness to +inf and hands the optimizer its
// seeded RNG. Plugins never count anything themselves, so every algorithm is
// measured the same way.
#include "framework/core/eigen.hpp"
#include <chrono>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "framework/core/budget.hpp"
#include "framework/core/problem.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {

struct TracePoint {
  long evaluations;  // evaluations spent when `best` was first reached
  double best;       // best-so-far fitness
};

class EvaluationContext {
 public:
  EvaluationContext(const Problem& problem, const Budget& budget, std::uint64_t seed);

  int dimension() const { return problem_.dimension(); }
  const Bounds& bounds() const { return problem_.bounds(); }
  Rng& rng() { return rng_; }

  // Threads each batch evaluation may use (EvaluationOptions::threads); 1
  // unless the caller runs nothing else in parallel. Values do not depend on it.
  void set_evaluation_threads(int threads) { options_.threads = threads; }
  int evaluation_threads() const { return options_.threads; }
  // Whether evaluate_against() may abandon losing candidates early (on by
  // default; results are the same either way, only the time differs).
  void set_early_abandonment(bool on) { early_abandonment_ = on; }

  // Evaluates the columns of X into f (resized to X.cols()). Returns how many
  // columns were evaluated, in order: fewer than X.cols() when the budget ran
  // out, and the rest of f is +inf. Throws std::logic_error for a point
  // outside the bounds (a plugin bug).
  Eigen::Index evaluate(const Eigen::MatrixXd& X, Eigen::VectorXd& f);
  // The same for a caller that only needs to know whether candidate i beats
  // threshold[i] (greedy one-to-one selection against its parent's
  // fitness): a candidate that loses may get a value above its threshold
  // instead of its exact fitness, when early abandonment is on and the
  // problem supports it. Thresholds are first raised to the best-so-far, so
  // an inexact value is never a new best: survivors, the best point and the
  // trace are exactly those of evaluate().
  Eigen::Index evaluate_against(const Eigen::MatrixXd& X, const Eigen::VectorXd& threshold,
                                Eigen::VectorXd& f);
  // One candidate; +inf when the budget is already spent.
  double evaluate(const Eigen::VectorXd& x);

  // Call at the top of each generation. Returns false when the trial must
  // stop (any budget reached); otherwise counts one more iteration.
  bool next_iteration();
  // True once any budget is reached.
  bool stopped();
  // Evaluations still allowed (LONG_MAX without an evaluation budget).
  long remaining_evaluations() const;

  // Polish support: the optimizer sees only the next `count` evaluations
  // as its budget (its schedules start now and end there); lifting the
  // limit hands the rest of the budget to the local search that follows.
  void limit_evaluations(long count) {
    phase_start_ = evaluations_;
    phase_limit_ = evaluations_ + count;
  }
  void lift_evaluation_limit();
  // Fraction of the budget used, in [0, 1]: the tau of schedules.
  double progress() const;

  long evaluations() const { return evaluations_; }
  long iterations() const { return iterations_; }
  double best_value() const { return best_value_; }
  const Eigen::VectorXd& best_point() const { return best_point_; }
  const std::vector<TracePoint>& trace() const { return trace_; }
  StopReason stop_reason() const { return stop_reason_; }
  double elapsed_seconds() const;

  // Called by the harness when the optimizer returns: an optimizer that
  // ended before any budget did is recorded as "converged".
  void finish();
  void fail() { stop_reason_ = StopReason::Failed; }

 private:
  Eigen::Index evaluate(const Eigen::MatrixXd& X, Eigen::VectorXd& f, std::span<const double> abandon_above);
  void record(const Eigen::Ref<const Eigen::VectorXd>& x, double value);
  void check_budget();
  std::optional<long> evaluation_limit() const;

  const Problem& problem_;
  Budget budget_;
  EvaluationOptions options_;
  bool early_abandonment_ = true;
  Rng rng_;
  std::chrono::steady_clock::time_point start_;
  std::optional<long> phase_limit_;
  long phase_start_ = 0;
  long evaluations_ = 0;
  long iterations_ = 0;
  double best_value_ = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_point_;
  std::vector<TracePoint> trace_;
  StopReason stop_reason_ = StopReason::Running;
};

}  // namespace hystbench
