// Aboulnasr & Mayyas's variable step (docs/control.md#vss_aboulnasr): the
// step follows the squared, smoothed correlation of successive errors,
// p(n) = beta p(n-1) + (1 - beta) e(n) e(n-1), in which white measurement
// noise averages out.
#include "plugins/controllers/variable_step.hpp"

namespace hystbench {
namespace {

class VssAboulnasr : public VariableStepFxlms {
 public:
  static ControllerInfo info() {
    auto specs = params(1.2e-4, "weight of p(n)^2 in the step recursion (error units^-4)");
    specs.push_back(ParamSpec::real("beta", 0.99, 0.0, 1.0, "memory of the error correlation p"));
    return {"vss_aboulnasr", "FxNLMS with Aboulnasr-Mayyas variable step (error correlation)",
            "T. Aboulnasr, K. Mayyas, A robust variable step-size LMS-type algorithm: analysis and "
            "simulations, IEEE Trans. Signal Processing 45(3):631-639, 1997, "
            "doi:10.1109/78.558478. RESOLUTION: gamma = (1 - alpha) mu_max / P0^2 with P0 = 0.5",
            specs};
  }
  explicit VssAboulnasr(const Params& p) : VariableStepFxlms(p), beta_(p.real("beta")) {}

 protected:
  double next_step(double e) override {
    correlation_ = beta_ * correlation_ + (1.0 - beta_) * e * previous_;
    previous_ = e;
    return use_then_advance(correlation_ * correlation_);
  }
  void reset_drive() override { correlation_ = previous_ = 0.0; }

 private:
  double beta_;
  double correlation_ = 0.0, previous_ = 0.0;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::VssAboulnasr)
