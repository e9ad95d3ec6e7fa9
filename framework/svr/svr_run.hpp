#pragma once
// What `hystbench svr` does with an experiment (docs/svr.md#the-svr-command):
// tune (epsilon, C, sigma) with the experiment's optimizer, train stage 1
// on every row of the stage 1 record, choose the ARX orders by AIC on the
// scan, then score the model, and the grey-box fit when given, on every
// test signal.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "framework/harness/trial_result.hpp"
#include "framework/svr/svr_experiment.hpp"

namespace hystbench {

// Errors over the scored part of one test signal.
struct SignalScore {
  double rmse = 0.0;           // free run
  double re = 0.0;             // relative error sqrt(sum e^2 / sum y^2), a fraction
  double max_error = 0.0;      // free run, absolute
  double rmse_one_step = 0.0;  // one step ahead with measured outputs
};

struct SvrTestRow {
  const SvrTestSignal* signal = nullptr;
  Eigen::Index scored_from = 0;  // first scored sample, relative to the signal
  Eigen::VectorXd u, y, y_svr, y_greybox;  // the whole signal (y_greybox empty without one)
  SignalScore svr;
  std::optional<SignalScore> greybox;
};

struct SvrResults {
  struct Search {
    TrialResult trial;  // the optimizer's run: best log10 values, trace
    SvrHyperparameters hyperparameters;
  } search;
  SvrHammerstein model;
  ArxSelection arx;
  std::vector<SvrTestRow> rows;
  double seconds = 0.0;
};

// `status` is told which step runs. Throws InputError when a step fails on
// these data (the search finds no finite fitness, no stable ARX order, the
// grey-box model diverges on a test record).
SvrResults run_svr(const SvrExperiment& x, int threads, const std::function<void(const std::string&)>& status);

// Errors of `model` against `y` from sample `from` on.
SignalScore score(const Eigen::VectorXd& y, const Eigen::VectorXd& model, const Eigen::VectorXd& one_step,
                  Eigen::Index from);

}  // namespace hystbench
