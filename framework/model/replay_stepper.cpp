#include "framework/model/replay_stepper.hpp"

#include <limits>

namespace hystbench {

// Effects without a stepper of their own replay their batch form.
std::unique_ptr<EffectStepper> Effect::stepper(std::span<const double> p, const StepContext& ctx) const {
  return std::make_unique<ReplayStepper>(*this, p, ctx);
}

ReplayStepper::ReplayStepper(const Effect& effect, std::span<const double> p, const StepContext& ctx)
    : effect_(&effect), p_(p.begin(), p.end()), ctx_(ctx) {}

void ReplayStepper::reset() {
  signal_.clear();
  stage_input_.clear();
  time_.clear();
}

double ReplayStepper::step(double signal, double stage_input) {
  time_.push_back(ctx_.sample_time * double(signal_.size()));
  signal_.push_back(signal);
  stage_input_.push_back(stage_input);
  const auto n = Eigen::Index(signal_.size());
  // apply() takes Eigen vectors and may change the signal: copies, every sample.
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(signal_.data(), n);
  const Eigen::VectorXd stage = Eigen::Map<const Eigen::VectorXd>(stage_input_.data(), n);
  const Eigen::VectorXd time = Eigen::Map<const Eigen::VectorXd>(time_.data(), n);
  SignalContext ctx{ctx_.sample_time, &time, &stage, ctx_.substeps, ctx_.hold};
  if (!effect_->apply(p_, ctx, out)) return std::numeric_limits<double>::quiet_NaN();
  return out[n - 1];
}

std::unique_ptr<EffectStepper> ReplayStepper::clone() const { return std::make_unique<ReplayStepper>(*this); }

}  // namespace hystbench
