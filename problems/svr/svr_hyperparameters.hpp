#pragma once
// Choosing the SVR's (epsilon, C, sigma) as an optimization problem
// (docs/svr.md#hyperparameters), so that any optimizer plugin tunes them and
// `hystbench run` compares optimizers on it. The decision variables are
// log10 epsilon, log10 C, log10 sigma; the fitness is a validation error of
// stage 1 on scaled targets:
//
//   blocked_cv       (default) contiguous folds: train on the others, mean
//                    squared one-step error on each fold; no sample's
//                    neighbour leaks into its own fold
//   libsvm_cv        libsvm's svm_cross_validation (random folds): the
//                    likely original of the seed's tooling; libsvm draws
//                    its folds from the C library's rand(), so every call
//                    is serialised and seeded with "cv_seed"
//   freerun_holdout  train on all but the last `holdout` fraction, simulate
//                    the held-out part in free run
//
// Experiment file:
//   "problem": {"type": "svr_hyperparameters", "data": "train.csv",
//               "segment": "train 1 Hz" (optional: only these samples),
//               "lags": {"m": 4, "n": 4}, "fitness": "blocked_cv", "folds": 5,
//               "max_rows": 1000, "log10_epsilon": [-3, -1], "log10_C": [-1, 3],
//               "log10_sigma": [1, 3]}
// (the defaults shown: the box where libsvm stays fast, docs/svr.md#hyperparameters)
// At most `max_rows` regression rows take part in any training (the record
// uniformly decimated; freerun_holdout decimates its training part); the
// final model is trained on all of them.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/core/problem.hpp"
#include "framework/core/registry.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench {

class SvrHyperparameterProblem : public Problem {
 public:
  static ProblemInfo info();
  // Throws InputError naming the key.
  SvrHyperparameterProblem(const Params& options, const std::filesystem::path& base_dir);

  std::string name() const override;
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const override;
  // Candidates train in parallel (each value independent of the others).
  void evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f,
                     const EvaluationOptions& options) const override;
  nlohmann::json describe() const override;

  double fitness(const SvrHyperparameters& h) const;

 private:
  enum class Fitness { BlockedCv, LibsvmCv, FreerunHoldout };
  double blocked_cv(const SvrHyperparameters& h) const;
  double libsvm_cv(const SvrHyperparameters& h) const;
  double freerun_holdout(const SvrHyperparameters& h) const;

  std::string data_name_;
  Eigen::VectorXd x_, y_;  // the training record
  SvrLags lags_;
  Eigen::Index max_rows_ = 1000;  // rows any validation trains on
  Eigen::MatrixXd rows_;  // scaled regression rows taking part
  Eigen::VectorXd targets_;
  Fitness fitness_ = Fitness::BlockedCv;
  int folds_ = 5;
  double holdout_ = 0.25;
  unsigned cv_seed_ = 1;
  Bounds bounds_;
};

}  // namespace hystbench
