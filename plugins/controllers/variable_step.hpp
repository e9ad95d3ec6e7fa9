#pragma once
// The recursion every variable-step rule here shares
// (docs/control.md#variable-step-rules):
//
//   mu(n+1) = clip(alpha mu(n) + gamma drive(n), mu_min, mu_max),  mu(0) = mu_max
//
// where each rule has its own drive: the squared error (Kwong), the squared
// error correlation (Aboulnasr), the normalised change of the error power
// (vss_fxlms). Steps are in the normalised domain unless "normalize" is
// turned off.
#include <algorithm>
#include <string>

#include "framework/control/fxlms_controller.hpp"

namespace hystbench {

class VariableStepFxlms : public FxlmsController {
 public:
  // The FxLMS parameters, then mu_min, mu_max, alpha and gamma.
  static std::vector<ParamSpec> params(double gamma, const std::string& gamma_doc) {
    auto specs = fxlms_params(true);
    specs.push_back(ParamSpec::real("mu_min", 0.001, 0.0, 1e6, "lower step bound"));
    specs.push_back(ParamSpec::real("mu_max", 0.03, 0.0, 1e6, "upper step bound, and mu(0)"));
    specs.push_back(ParamSpec::real("alpha", 0.999, 0.0, 1.0, "memory of the step recursion"));
    specs.push_back(ParamSpec::real("gamma", gamma, 0.0, 1e6, gamma_doc));
    return specs;
  }
  explicit VariableStepFxlms(const Params& p)
      : FxlmsController(fxlms_options(p)),
        mu_min_(p.real("mu_min")),
        mu_max_(p.real("mu_max")),
        alpha_(p.real("alpha")),
        gamma_(p.real("gamma")),
        mu_(mu_max_) {
    if (mu_min_ > mu_max_)
      throw InputError("params.mu_min (" + std::to_string(mu_min_) + ") is above params.mu_max (" +
                       std::to_string(mu_max_) + "); give mu_min <= mu_max");
  }

 protected:
  void reset_step() override {
    mu_ = mu_max_;
    reset_drive();
  }
  // The current step, then the recursion driven by `drive` for the next one.
  double use_then_advance(double drive) {
    const double used = mu_;
    advance(drive);
    return used;
  }
  // The recursion driven by `drive`, whose result is used now.
  double advance_then_use(double drive) {
    advance(drive);
    return mu_;
  }
  double mu_max() const { return mu_max_; }
  virtual void reset_drive() = 0;

 private:
  void advance(double drive) { mu_ = std::clamp(alpha_ * mu_ + gamma_ * drive, mu_min_, mu_max_); }

  double mu_min_, mu_max_, alpha_, gamma_;
  double mu_;
};

}  // namespace hystbench
