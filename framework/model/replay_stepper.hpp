#pragma once
// The default streaming form of an effect (Effect::stepper): at every
// sample, apply() runs on the whole history and the last value is the
// output. Any effect works this way, out-of-tree ones included, and the
// result is exactly the batch output whenever the effect is causal (apply's
// output at k depends on samples up to k only). The price is O(k) work and
// memory at sample k: effects meant for long streams write a stepper of
// their own.
#include "framework/core/eigen.hpp"
#include <memory>
#include <span>
#include <vector>

#include "framework/model/effect.hpp"

namespace hystbench {

class ReplayStepper final : public EffectStepper {
 public:
  // `effect` must outlive the stepper.
  ReplayStepper(const Effect& effect, std::span<const double> p, const StepContext& ctx);
  void reset() override;
  // NaN when apply() returns false on the history.
  double step(double signal, double stage_input) override;
  std::unique_ptr<EffectStepper> clone() const override;

 private:
  const Effect* effect_;
  std::vector<double> p_;
  StepContext ctx_;
  // What entered the effect and its stage at samples 0..k, and k·Ts.
  std::vector<double> signal_, stage_input_, time_;
};

}  // namespace hystbench
