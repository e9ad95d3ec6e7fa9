#pragma once
// u = 0 whatever the error: the reference every controller is measured
// against (the loop runs it with the same noise), and the `off` plugin.
#include <cstdint>

#include "framework/control/control_loop.hpp"
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

// The loop without control, with the noise of `settings` and without the
// divergence checks: it is the reference the checks are measured against.
LoopTrace run_uncontrolled(const LoopPaths& paths, LoopSettings settings, std::uint64_t noise_seed);

}  // namespace hystbench
