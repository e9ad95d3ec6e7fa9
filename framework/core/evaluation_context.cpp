#include "framework/core/evaluation_context.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

namespace hystbench {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

EvaluationContext::EvaluationContext(const Problem& problem, const Budget& budget,
                                     std::uint64_t seed)
    : problem_(problem), budget_(budget), rng_(seed), start_(std::chrono::steady_clock::now()) {
  best_point_ = (problem.bounds().lower + problem.bounds().upper) / 2;
}

double EvaluationContext::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::optional<long> EvaluationContext::evaluation_limit() const {
  if (phase_limit_ && budget_.evaluations) return std::min(*phase_limit_, *budget_.evaluations);
  return phase_limit_ ? phase_limit_ : budget_.evaluations;
}

long EvaluationContext::remaining_evaluations() const {
  const auto limit = evaluation_limit();
  return limit ? std::max(0L, *limit - evaluations_) : LONG_MAX;
}

void EvaluationContext::lift_evaluation_limit() {
  phase_limit_.reset();
  phase_start_ = 0;
  if (stop_reason_ == StopReason::Evaluations && remaining_evaluations() > 0)
    stop_reason_ = StopReason::Running;
}

void EvaluationContext::check_budget() {
  if (stop_reason_ != StopReason::Running) return;
  if (budget_.target && best_value_ <= *budget_.target)
    stop_reason_ = StopReason::Target;
  else if (const auto limit = evaluation_limit(); limit && evaluations_ >= *limit)
    stop_reason_ = StopReason::Evaluations;
  else if (budget_.seconds && elapsed_seconds() >= *budget_.seconds)
    stop_reason_ = StopReason::Seconds;
}

bool EvaluationContext::stopped() {
  check_budget();
  return stop_reason_ != StopReason::Running;
}

bool EvaluationContext::next_iteration() {
  if (stopped()) return false;
  if (budget_.iterations && iterations_ >= *budget_.iterations) {
    stop_reason_ = StopReason::Iterations;
    return false;
  }
  ++iterations_;
  return true;
}

double EvaluationContext::progress() const {
  double tau = 0.0;
  if (const auto limit = evaluation_limit()) {
    const long start = phase_limit_ ? phase_start_ : 0;
    tau = *limit > start ? std::max(tau, double(evaluations_ - start) / double(*limit - start)) : 1.0;
  }
  if (budget_.iterations) tau = std::max(tau, double(iterations_) / double(*budget_.iterations));
  if (budget_.seconds) tau = std::max(tau, elapsed_seconds() / *budget_.seconds);
  return std::min(tau, 1.0);
}

void EvaluationContext::record(const Eigen::Ref<const Eigen::VectorXd>& x, double value) {
  ++evaluations_;
  if (value < best_value_) {
    best_value_ = value;
    best_point_ = x;
    trace_.push_back({evaluations_, value});
  }
}

Eigen::Index EvaluationContext::evaluate(const Eigen::MatrixXd& X, Eigen::VectorXd& f) {
  return evaluate(X, f, {});
}

Eigen::Index EvaluationContext::evaluate_against(const Eigen::MatrixXd& X, const Eigen::VectorXd& threshold,
                                                 Eigen::VectorXd& f) {
  if (threshold.size() != X.cols())
    throw std::logic_error("evaluate_against: " + std::to_string(threshold.size()) + " thresholds for " +
                           std::to_string(X.cols()) + " candidates");
  if (!early_abandonment_) return evaluate(X, f, {});
  // A threshold below the best-so-far could let an abandoned (inexact)
  // value into the trace; at or above it, that value is never a new best.
  const Eigen::VectorXd limit = threshold.cwiseMax(best_value_);
  return evaluate(X, f, std::span<const double>(limit.data(), limit.size()));
}

Eigen::Index EvaluationContext::evaluate(const Eigen::MatrixXd& X, Eigen::VectorXd& f,
                                         std::span<const double> abandon_above) {
  if (X.rows() != dimension())
    throw std::logic_error("evaluate: candidates have " + std::to_string(X.rows()) +
                           " rows, the problem has dimension " + std::to_string(dimension()));
  f.setConstant(X.cols(), kInf);
  if (stopped()) return 0;
  const Eigen::Index n = std::min<Eigen::Index>(X.cols(), remaining_evaluations());
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!bounds().contains(X.col(i)))
      throw std::logic_error("optimizer evaluated a point outside the bounds");
  }
  EvaluationOptions options = options_;
  if (!abandon_above.empty()) options.abandon_above = abandon_above.first(n);
  problem_.evaluate_with(X.leftCols(n), f.head(n), options);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!std::isfinite(f[i])) f[i] = kInf;
    record(X.col(i), f[i]);
  }
  check_budget();
  return n;
}

double EvaluationContext::evaluate(const Eigen::VectorXd& x) {
  Eigen::VectorXd f;
  evaluate(Eigen::MatrixXd(x), f);
  return f[0];
}

void EvaluationContext::finish() {
  check_budget();
  if (stop_reason_ == StopReason::Running) stop_reason_ = StopReason::Converged;
  // Close the trace at the final evaluation count so curves reach the end.
  if (!trace_.empty() && trace_.back().evaluations != evaluations_)
    trace_.push_back({evaluations_, best_value_});
}

}  // namespace hystbench
