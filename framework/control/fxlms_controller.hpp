#pragma once
// The filtered-reference LMS controller shared by every FxLMS variant
// (docs/control.md#fxlms): an FIR filter W of `taps` weights on the
// reference, adapted by
//
//   w <- (1 - mu leakage) w - mu_n e(n) x'_vec(n),
//   mu_n = mu                                (plain FxLMS)
//   mu_n = mu / (delta + x'_vec^T x'_vec)    (normalised, FxNLMS)
//
// with the sign of physical superposition e = d + S u. The variants differ
// only in how mu is chosen at each sample: a plugin derives from
// FxlmsController and supplies next_step().
#include "framework/core/eigen.hpp"
#include <vector>

#include "framework/control/controller.hpp"
#include "framework/control/tapped_delay_line.hpp"
#include "framework/core/error.hpp"

namespace hystbench {

struct FxlmsOptions {
  int taps = 32;
  double leakage = 0.0;
  double output_limit = 10.0;  // |u| is clipped to this
  bool normalize = true;
  double delta = 1e-6;  // regularisation of the normalisation
};

// The parameters every FxLMS variant accepts, to be followed by the
// variant's own; `normalize` is the default of the "normalize" flag.
std::vector<ParamSpec> fxlms_params(bool normalize);
FxlmsOptions fxlms_options(const Params& params);

class FxlmsController : public Controller {
 public:
  explicit FxlmsController(const FxlmsOptions& options);

  void reset() final;
  double output(double x) final;
  void adapt(double error, double filtered) final;
  double step_size() const final { return step_; }
  double weight_norm() const final { return w_.norm(); }

 protected:
  // The step mu for the adaptation at this sample, from the error e(n); called
  // once per sample, in order.
  virtual double next_step(double error) = 0;
  // Back to the initial step-size state.
  virtual void reset_step() = 0;

 private:
  FxlmsOptions options_;
  Eigen::VectorXd w_;
  TappedDelayLine reference_, filtered_;
  double step_ = 0.0;
};

}  // namespace hystbench
