// The uncontrolled baseline: u = 0 whatever the error. Every experiment
// also runs it on its own, with the same noise, as the reference of the
// suppression efficiency (docs/control.md#metrics).
#include "framework/control/controller.hpp"

namespace hystbench {
namespace {

class Off : public Controller {
 public:
  static ControllerInfo info() {
    return {"off", "No control: u = 0 (the uncontrolled baseline)", "", {}};
  }
  explicit Off(const Params&) {}
  void reset() override {}
  double output(double) override { return 0.0; }
  void adapt(double, double) override {}
  double step_size() const override { return 0.0; }
  double weight_norm() const override { return 0.0; }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::Off)
