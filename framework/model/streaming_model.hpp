#pragma once
// A model run one sample at a time (docs/models.md#streaming-models):
// reset(), then step(u[k]) -> y[k] for k = 0, 1, ...; causal, and holding
// its own state, so that a model can sit inside a loop (a plant, or an
// estimate of one). Fed the samples of a record, it gives what
// Model::simulate gives on that record under the same input hold (to
// rounding: the catalog effects share their per-sample code between the two
// forms). Works in normalised units, like simulate().
#include "framework/core/eigen.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "framework/model/model.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

class StreamingModel final : public SignalStream {
 public:
  // The model with parameters `x` at `sample_time`, its ODE effects
  // reconstructing the input with `hold` (the model's own hold is the
  // offline one and is not used). Throws InputError naming `where` when the
  // hold is not causal: the spline and the band-limited hold need samples
  // not yet seen.
  StreamingModel(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& x, double sample_time,
                 InputHold hold = InputHold::Linear, const std::string& where = "stream");
  StreamingModel(const StreamingModel& other);
  StreamingModel& operator=(const StreamingModel&) = delete;

  // False when an effect's parameters are invalid (where simulate() returns
  // false whatever the record): step() then returns NaN.
  bool valid() const { return valid_; }
  InputHold hold() const { return hold_; }

  void reset() override;
  // NaN from the first sample at which an effect diverges (where simulate()
  // returns false for the record) until reset().
  double step(double u) override;
  std::unique_ptr<SignalStream> clone() const override;

  // step() in two halves, step(u) == step_back(step_front(u)): the static
  // and hysteretic front (input stage, gain, nonlinearity) gives w, the
  // signal that enters the dynamics; the back (dynamics and output stages)
  // gives y. Inverse compensation cancels the front and leaves the back to
  // a linear controller.
  double step_front(double u);
  double step_back(double w);
  // The front's state taken from `from`, a copy of this model: one sample's
  // front can then be tried for many inputs.
  void copy_front_state(const StreamingModel& from);

 private:
  using Steppers = std::vector<std::unique_ptr<EffectStepper>>;
  // Runs one stage's effects on `signal`; false once one of them diverged.
  static bool run_stage(Steppers& stage, double& signal, double stage_input);
  double checked(bool finite, double signal);

  Model model_;  // keeps alive the effects the steppers refer to
  InputHold hold_;
  double gain_;
  std::array<Steppers, 4> stages_;  // by EffectStage, each in chain order
  bool valid_ = true;
  bool diverged_ = false;
};

}  // namespace hystbench
