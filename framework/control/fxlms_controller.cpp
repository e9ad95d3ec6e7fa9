#include "framework/control/fxlms_controller.hpp"

#include <algorithm>

namespace hystbench {

std::vector<ParamSpec> fxlms_params(bool normalize) {
  return {
      ParamSpec::integer("taps", 32, 1, 4096, "FIR weights on the reference"),
      ParamSpec::real("leakage", 0.0, 0.0, 1e3,
                      "leakage nu: w <- (1 - mu nu) w - ...; 0 is no leakage"),
      ParamSpec::real("output_limit", 10.0, 1e-12, 1e12,
                      "the control output is clipped to [-limit, limit] (amplifier range, V)"),
      ParamSpec::boolean("normalize", normalize,
                         "divide the step by delta + |x'|^2 (FxNLMS), so mu is scale-free"),
      ParamSpec::real("delta", 1e-6, 0.0, 1e6, "regularisation of the normalisation"),
  };
}

FxlmsOptions fxlms_options(const Params& p) {
  return {p.integer("taps"), p.real("leakage"), p.real("output_limit"), p.boolean("normalize"),
          p.real("delta")};
}

FxlmsController::FxlmsController(const FxlmsOptions& options)
    : options_(options),
      w_(Eigen::VectorXd::Zero(options.taps)),
      reference_(options.taps),
      filtered_(options.taps) {}

void FxlmsController::reset() {
  w_.setZero();
  reference_.reset(options_.taps);
  filtered_.reset(options_.taps);
  step_ = 0.0;
  reset_step();
}

double FxlmsController::output(double x) {
  reference_.push(x);
  const double u = w_.dot(reference_.recent());
  return std::clamp(u, -options_.output_limit, options_.output_limit);
}

void FxlmsController::adapt(double error, double filtered) {
  filtered_.push(filtered);
  const auto xf = filtered_.recent();
  step_ = next_step(error);
  const double gain =
      options_.normalize ? step_ / (options_.delta + xf.squaredNorm()) : step_;
  if (options_.leakage > 0.0) w_ *= 1.0 - step_ * options_.leakage;
  w_ -= (gain * error) * xf;
}

}  // namespace hystbench
