// Filtered-x LMS with a constant raw step (docs/control.md#fxlms). The step
// bound scales with the filtered-reference power: about 2 / (P_x' (L + 2D))
// for L taps and a path delay of D samples.
#include "plugins/controllers/fixed_step.hpp"

namespace hystbench {
namespace {

class Fxlms : public FixedStepFxlms {
 public:
  static ControllerInfo info() {
    return {"fxlms", "Filtered-x LMS, constant step mu (not normalised)", kFxlmsCitation,
            params(false, 2e-4,
                   "step size; about mu_bar / (taps P_x') of the normalised form")};
  }
  using FixedStepFxlms::FixedStepFxlms;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::Fxlms)
