#pragma once
// The SVR Hammerstein-like model of seed 002 (docs/svr.md): stage 1, an
// epsilon-SVR NARX that predicts the scaled output one step ahead from the
// last m+1 inputs and n+1 outputs,
//
//   w(k+1) = f_SVR( x(k), ..., x(k-m), w(k), ..., w(k-n) [, r(k)] ),
//
// optionally with the input's rate r(k) = tanh((x(k) - x(k-1)) / s), s the
// largest step of the scaled training input (not in the seed: an ablation),
// trained at 1 Hz where the actuator's dynamics do not show (series-parallel:
// measured outputs in the regressors); stage 2, an ARX block from w to y
// fitted on a frequency scan, with w the free-running stage 1 output.
// Inputs and outputs are min-max scaled to [-1, 1] with ranges stored in the
// model. RECONSTRUCTION: the seed gives the structure, m = n = 4 and the
// orders by AIC, not how the stages are coupled (docs/svr.md#stage-2).
#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "framework/svr/arx_fit.hpp"
#include "framework/svr/svr_regressor.hpp"

namespace hystbench {

// Stage 1's regressors: the lags, and whether the input's rate is one more.
struct SvrLags {
  int m = 4;  // input lags: x(k) .. x(k-m)
  int n = 4;  // output lags: w(k) .. w(k-n)
  bool input_rate = false;  // r(k) from x(k) - x(k-1) as the last regressor
  int dimension() const { return m + n + 2 + (input_rate ? 1 : 0); }
  int warmup() const { return std::max({m, n, input_rate ? 1 : 0}) + 1; }  // samples taken as measured
};

// The rate regressor of a step from scaled input a to b: bounded, so that a
// test faster than the training record saturates it instead of leaving the
// kernel's reach.
inline double rate_regressor(double a, double b, double step) { return std::tanh((b - a) / step); }

// How stage 2 sees stage 1 on the scan: its free run (the signal the whole
// model passes on when simulated), or its one-step prediction from the
// measured outputs (series-parallel, as stage 1 was trained).
enum class SvrCoupling { FreeRun, OneStep };

// Maps [lo, hi] onto [-1, 1].
struct MinMaxScale {
  double lo = -1.0, hi = 1.0;
  static MinMaxScale of(const Eigen::VectorXd& x);
  double to_unit(double v) const { return 2.0 * (v - lo) / (hi - lo) - 1.0; }
  double from_unit(double s) const { return lo + 0.5 * (s + 1.0) * (hi - lo); }
};

class SvrHammerstein {
 public:
  // Stage 1 on (x, y). Throws InputError naming `where` when the record is
  // shorter than the lags need, constant, or the hyperparameters invalid.
  // `max_rows` > 0 trains on at most that many rows (decimate()).
  static SvrHammerstein fit_stage1(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const SvrLags& lags,
                                   const SvrHyperparameters& h, const std::string& where,
                                   Eigen::Index max_rows = 0);
  // The rows and targets stage 1 trains on, scaled by the record's ranges
  // (hyperparameter tuning validates on them).
  static void regression_rows(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const SvrLags& lags,
                              Eigen::MatrixXd& rows, Eigen::VectorXd& targets);

  // Keeps every k-th row, the least k that leaves at most `most`, so the
  // rows kept spread over the whole record.
  static void decimate(Eigen::MatrixXd& rows, Eigen::VectorXd& targets, Eigen::Index most);

  // Stage 2 on a scan (x, y): AIC over p, q in 1..max. Returns the grid.
  ArxSelection fit_stage2(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int p_max, int q_max,
                          const std::string& where, SvrCoupling coupling = SvrCoupling::FreeRun);

  // Stage 1 alone, one step ahead with measured outputs: y_hat(k+1) from
  // y(k..k-n). The first lags.warmup() samples are copied from y.
  Eigen::VectorXd one_step(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const;
  // Stage 1 alone in free run (its own past outputs), started from the
  // first lags.warmup() measured samples.
  Eigen::VectorXd stage1_free_run(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const;
  // The whole model in free run: stage 1, then the ARX block in output-error
  // form (stage 1 alone when no stage 2 was fitted).
  Eigen::VectorXd simulate(const Eigen::VectorXd& x, const Eigen::VectorXd& y_start) const;

  const SvrLags& lags() const { return lags_; }
  const MinMaxScale& input_scale() const { return x_scale_; }
  const MinMaxScale& output_scale() const { return y_scale_; }
  const SvrRegressor& regressor() const { return svr_; }
  // The rate regressor of a step from scaled input a to b (0 without one).
  double rate_feature(double a, double b) const { return rate_regressor(a, b, rate_step_); }
  const std::optional<ArxFit>& arx() const { return arx_; }

  nlohmann::json to_json() const;
  // "svr_hammerstein(m = 4, n = 4, ARX 2/2)": the model's name in reports.
  std::string describe() const;
  // Whether a JSON file holds an SVR model (else, e.g., a catalog fit.json).
  static bool is_model_file(const nlohmann::json& j) {
    return j.is_object() && j.value("model", nlohmann::json()) == "svr_hammerstein";
  }
  // Throws InputError naming `where` and the key.
  static SvrHammerstein from_json(const nlohmann::json& j, const std::string& where);

 private:
  SvrHammerstein(SvrRegressor svr, SvrLags lags, MinMaxScale x_scale, MinMaxScale y_scale, double rate_step)
      : svr_(std::move(svr)), lags_(lags), x_scale_(x_scale), y_scale_(y_scale), rate_step_(rate_step) {}

  SvrRegressor svr_;
  SvrLags lags_;
  MinMaxScale x_scale_, y_scale_;
  double rate_step_ = 1.0;  // s of the rate regressor (1 without one)
  std::optional<ArxFit> arx_;
};

}  // namespace hystbench
