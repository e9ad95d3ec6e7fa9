// Kwong & Johnston's variable step (docs/control.md#vss_kwong): the step
// follows the squared error, mu(n+1) = alpha mu(n) + gamma e(n)^2, clipped.
// Large while the error is large, but also driven up by measurement noise,
// since gamma multiplies the error's absolute level.
#include "plugins/controllers/variable_step.hpp"

namespace hystbench {
namespace {

class VssKwong : public VariableStepFxlms {
 public:
  static ControllerInfo info() {
    return {"vss_kwong", "FxNLMS with Kwong-Johnston variable step (squared error)",
            "R. H. Kwong, E. W. Johnston, A variable step size LMS algorithm, IEEE Trans. Signal "
            "Processing 40(7):1633-1642, 1992, doi:10.1109/78.143435. RESOLUTION: gamma = (1 - "
            "alpha) mu_max / P0 with P0 = 0.5, the uncontrolled error power of the normalised "
            "beam",
            params(6e-5, "weight of e(n)^2 in the step recursion (error units^-2)")};
  }
  using VariableStepFxlms::VariableStepFxlms;

 protected:
  double next_step(double e) override { return use_then_advance(e * e); }
  void reset_drive() override {}
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::VssKwong)
