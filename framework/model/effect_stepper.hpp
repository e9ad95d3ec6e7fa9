#pragma once
// The streaming form of an effect: its state, advanced one sample at a time
// (docs/models.md#streaming-models). Effect::stepper() makes one from the
// effect's parameters; StreamingModel chains them like Model::simulate
// chains apply().
//
// A catalog effect writes its per-sample update once, as an inline function
// over a small state struct, and calls it from both its batch loop and its
// stepper (kernel_stepper below): the two then agree bit for bit.
#include <memory>
#include <utility>

#include "framework/model/effect_lanes.hpp"
#include "framework/model/input_hold.hpp"

namespace hystbench {

// What a stepper sees besides its parameters (the streaming SignalContext).
// Time is k·sample_time at sample k.
struct StepContext {
  double sample_time = 0.0;
  // Reconstruction of the input between samples for ODE effects; always
  // causal in a stream.
  InputHold hold = InputHold::Linear;
  int substeps = 0;  // as SignalContext::substeps
};

class EffectStepper {
 public:
  virtual ~EffectStepper() = default;
  // Back to rest, as at the start of a record.
  virtual void reset() = 0;
  // Sample k: `signal` is what enters the effect at k, `stage_input` what
  // SignalContext::stage_input holds at k. Returns what apply() writes to
  // signal[k] given samples 0..k. Non-finite once the effect has diverged
  // (where apply() returns false).
  virtual double step(double signal, double stage_input) = 0;
  // An independent copy in the current state.
  virtual std::unique_ptr<EffectStepper> clone() const = 0;
  // Takes the state of `from`, a stepper of the same effect and parameters,
  // without allocating; false when this stepper cannot (then clone). An
  // inverse tries many inputs at one sample from the same state.
  virtual bool copy_state(const EffectStepper& /*from*/) { return false; }
};

// A stepper from a per-sample kernel(state, signal, stage_input) -> output
// and a State whose value-initialised form is the state at rest.
template <class State, class Kernel>
class KernelStepper final : public EffectStepper {
 public:
  explicit KernelStepper(Kernel kernel) : kernel_(std::move(kernel)) {}
  void reset() override { state_ = State{}; }
  double step(double signal, double stage_input) override { return kernel_(state_, signal, stage_input); }
  std::unique_ptr<EffectStepper> clone() const override { return std::make_unique<KernelStepper>(*this); }
  bool copy_state(const EffectStepper& from) override {
    const auto* same = dynamic_cast<const KernelStepper*>(&from);
    if (same) state_ = same->state_;
    return same != nullptr;
  }

 private:
  Kernel kernel_;
  State state_{};
};

template <class State, class Kernel>
std::unique_ptr<EffectStepper> kernel_stepper(Kernel kernel) {
  return std::make_unique<KernelStepper<State, Kernel>>(std::move(kernel));
}

// The state of an effect that has none (a static map).
struct Stateless {};

// The stepper of an effect whose parameters leave the signal unchanged.
inline std::unique_ptr<EffectStepper> pass_through_stepper() {
  return kernel_stepper<Stateless>([](Stateless&, double signal, double) { return signal; });
}

// The stepper for a parameter setup (effect_lanes.hpp): none when the
// parameters are invalid, a pass-through, or make() when the effect runs.
template <class Make>
std::unique_ptr<EffectStepper> stepper_for(EffectSetup setup, Make make) {
  if (setup == EffectSetup::Invalid) return nullptr;
  if (setup == EffectSetup::PassThrough) return pass_through_stepper();
  return make();
}

}  // namespace hystbench
