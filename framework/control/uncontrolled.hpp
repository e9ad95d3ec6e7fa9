#pragma once
// u = 0 whatever the error: the reference every controller is measured
// against (the loop runs it with the same noise), and the `off` plugin.
#include "framework/control/controller.hpp"

namespace hystbench {

class Uncontrolled : public Controller {
 public:
  void reset() override {}
  double output(double) override { return 0.0; }
  void adapt(double, double) override {}
  double step_size() const override { return 0.0; }
  double weight_norm() const override { return 0.0; }
};

}  // namespace hystbench
