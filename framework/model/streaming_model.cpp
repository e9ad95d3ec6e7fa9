#include "framework/model/streaming_model.hpp"

#include <cmath>
#include <limits>
#include <span>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t index_of(EffectStage stage) { return static_cast<std::size_t>(stage); }

}  // namespace

StreamingModel::StreamingModel(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& x,
                               double sample_time, InputHold hold, const std::string& where)
    : model_(model), hold_(hold), gain_(x[0]) {
  if (!is_causal(hold))
    throw InputError(where + ": a stream needs a causal input hold (linear or zoh), not " +
                     to_string(hold) + ", which fits the whole record");
  const StepContext ctx{sample_time, hold, model.substeps()};
  for (const auto& e : model_.chain()) {
    std::span<const double> p(x.data() + e.offset, e.info->params.size());
    auto stepper = e.effect->stepper(p, ctx);
    if (!stepper) valid_ = false;
    stages_[index_of(e.info->stage)].push_back(std::move(stepper));
  }
}

StreamingModel::StreamingModel(const StreamingModel& other)
    : model_(other.model_),
      hold_(other.hold_),
      gain_(other.gain_),
      valid_(other.valid_),
      diverged_(other.diverged_) {
  for (std::size_t s = 0; s < stages_.size(); ++s)
    for (const auto& stepper : other.stages_[s])
      stages_[s].push_back(stepper ? stepper->clone() : nullptr);
}

void StreamingModel::reset() {
  for (auto& stage : stages_)
    for (auto& stepper : stage)
      if (stepper) stepper->reset();
  diverged_ = false;
}

bool StreamingModel::run_stage(Steppers& stage, double& signal, double stage_input) {
  for (auto& stepper : stage) {
    signal = stepper->step(signal, stage_input);
    // A later effect may turn a diverged signal finite again (saturation's
    // tanh), so each effect is checked, as apply() checks its own state.
    if (!std::isfinite(signal)) return false;
  }
  return true;
}

double StreamingModel::checked(bool finite, double signal) {
  if (finite && std::isfinite(signal)) return signal;
  diverged_ = true;
  return kNaN;
}

double StreamingModel::step_front(double u) {
  if (!valid_ || diverged_) return kNaN;
  // The stage plumbing of Model::simulate, one sample at a time.
  double signal = u;
  bool finite = run_stage(stages_[index_of(EffectStage::Input)], signal, u);
  const double v = signal;
  signal *= gain_;
  finite = finite && run_stage(stages_[index_of(EffectStage::Nonlinearity)], signal, v);
  return checked(finite, signal);
}

double StreamingModel::step_back(double w) {
  if (!valid_ || diverged_) return kNaN;
  double signal = w;
  bool finite = true;
  for (EffectStage stage : {EffectStage::Dynamics, EffectStage::Output})
    finite = finite && run_stage(stages_[index_of(stage)], signal, signal);
  return checked(finite, signal);
}

double StreamingModel::step(double u) { return step_back(step_front(u)); }

// A stepper without copy_state (an out-of-tree effect's replay stepper) is
// cloned instead: correct, but it allocates at every trial.
void StreamingModel::copy_front_state(const StreamingModel& from) {
  if (!valid_ || !from.valid_) return;
  for (EffectStage stage : {EffectStage::Input, EffectStage::Nonlinearity}) {
    Steppers& mine = stages_[index_of(stage)];
    const Steppers& theirs = from.stages_[index_of(stage)];
    for (std::size_t i = 0; i < mine.size(); ++i)
      if (!mine[i]->copy_state(*theirs[i])) mine[i] = theirs[i]->clone();
  }
  diverged_ = from.diverged_;
}

std::unique_ptr<SignalStream> StreamingModel::clone() const {
  return std::make_unique<StreamingModel>(*this);
}

}  // namespace hystbench
