// Normalised filtered-x LMS with a constant step (docs/control.md#fxlms):
// the step divided by delta + |x'_vec|^2, so the same mu suits any sensor
// and actuator scale.
#include "plugins/controllers/fixed_step.hpp"

namespace hystbench {
namespace {

class Fxnlms : public FixedStepFxlms {
 public:
  static ControllerInfo info() {
    return {"fxnlms", "Normalised filtered-x LMS, constant step mu_bar", kFxlmsCitation,
            params(true, 0.003,
                   "normalised step mu_bar (0 < mu_bar < 2; on a lightly damped path far "
                   "smaller, 0.001-0.03)")};
  }
  using FixedStepFxlms::FixedStepFxlms;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::Fxnlms)
