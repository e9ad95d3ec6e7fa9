#pragma once
// A problem is "bounds + batch fitness": everything an optimizer may know.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

namespace hystbench {

// The search box. Components are named so that tables and JSON can say which
// parameter a value belongs to.
struct Bounds {
  Eigen::VectorXd lower;
  Eigen::VectorXd upper;
  std::vector<std::string> names;

  int dimension() const { return static_cast<int>(lower.size()); }
  bool contains(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // x with every component moved into [lower, upper].
  Eigen::VectorXd clamp(const Eigen::Ref<const Eigen::VectorXd>& x) const;
};

// How one batch evaluation may run, decided by the caller that owns the
// threads. The harness runs either several trials in parallel or the
// candidates of one batch in parallel, never both: one active level of
// parallelism, so the cores are not oversubscribed.
struct EvaluationOptions {
  // OpenMP threads the call may spread its candidates over; 1 keeps it on
  // the calling thread.
  int threads = 1;
  // Early abandonment, for callers that only compare candidate i with
  // abandon_above[i] (greedy selection against its parent): a problem may
  // stop a candidate whose partial fitness already exceeds that value and
  // report any value above it. Empty: every candidate is evaluated in full.
  // Problems are free to ignore it.
  std::span<const double> abandon_above;
};

class Problem {
 public:
  virtual ~Problem() = default;

  // Short identifier for reports, e.g. "hammerstein(default.csv)".
  virtual std::string name() const = 0;
  virtual const Bounds& bounds() const = 0;
  // Fitness of each column of X (dimension x n candidates) into f (size n).
  // Must be safe to call from several threads at once. May return NaN or
  // Inf; the evaluation context maps those to +inf.
  virtual void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                        Eigen::Ref<Eigen::VectorXd> f) const = 0;
  // The framework's entry point: evaluate() with the caller's options.
  // Problems that can share a batch between threads override it; the
  // values must not depend on options.threads. The default ignores them.
  virtual void evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f,
                             const EvaluationOptions& /*options*/) const {
    evaluate(X, f);
  }
  // Facts for summary.json: data file, known optimum, noise floor, ...
  virtual nlohmann::json describe() const { return {{"name", name()}}; }

  int dimension() const { return bounds().dimension(); }
};

// Optional capability of problems whose candidates are models of a measured
// signal: the harness uses it to draw model-vs-measurement figures.
class SignalModelProblem {
 public:
  virtual ~SignalModelProblem() = default;
  virtual const Eigen::VectorXd& time() const = 0;
  virtual const Eigen::VectorXd& input() const = 0;
  virtual const Eigen::VectorXd& measured() const = 0;
  // One label per sample (e.g. "sine_5Hz"), or empty.
  virtual const std::vector<std::string>& segments() const = 0;
  // Physical units of u and y for axis titles ("V", "µm"); empty if unknown.
  virtual std::string input_unit() const { return ""; }
  virtual std::string output_unit() const { return ""; }
  virtual Eigen::VectorXd simulate(const Eigen::Ref<const Eigen::VectorXd>& x) const = 0;
};

// Optional capability of problems whose fitness is a sum of squares,
// f(x) = sum_i r_i(x)^2: local methods that exploit that structure
// (Levenberg-Marquardt polish) need the residual vector, not just its sum.
class LeastSquaresProblem {
 public:
  virtual ~LeastSquaresProblem() = default;
  virtual Eigen::Index residual_count() const = 0;
  // r (size residual_count()) for candidate x. Only called for candidates
  // whose fitness is finite; r.squaredNorm() equals that fitness up to
  // rounding (the summation order may differ).
  virtual void residuals(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> r) const = 0;
};

}  // namespace hystbench
