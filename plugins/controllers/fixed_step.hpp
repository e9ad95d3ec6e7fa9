#pragma once
// FxLMS with a constant step, plain (fxlms.cpp) or normalised (fxnlms.cpp).
#include "framework/control/fxlms_controller.hpp"

namespace hystbench {

class FixedStepFxlms : public FxlmsController {
 public:
  // The FxLMS parameters and "mu" with the given default.
  static std::vector<ParamSpec> params(bool normalize, double mu, const std::string& mu_doc) {
    auto specs = fxlms_params(normalize);
    specs.push_back(ParamSpec::real("mu", mu, 0.0, 1e6, mu_doc));
    return specs;
  }
  explicit FixedStepFxlms(const Params& p) : FxlmsController(fxlms_options(p)), mu_(p.real("mu")) {}

 protected:
  double next_step(double) override { return mu_; }
  void reset_step() override {}

 private:
  double mu_;
};

inline const char* kFxlmsCitation =
    "S. M. Kuo, D. R. Morgan, Active Noise Control Systems: Algorithms and DSP "
    "Implementations, Wiley, 1996; S. M. Kuo, D. R. Morgan, Active noise control: a tutorial "
    "review, Proc. IEEE 87(6):943-973, 1999, doi:10.1109/5.763310";

}  // namespace hystbench
