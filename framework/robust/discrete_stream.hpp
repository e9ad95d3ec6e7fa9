#pragma once
// A discrete single-input single-output system run one sample at a time:
// out = C s + D in, then s ← A s + B in. A controller or a filter in a
// sampled loop.
#include <memory>

#include "framework/core/error.hpp"
#include "framework/model/signal_stream.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

class DiscreteStream final : public SignalStream {
 public:
  explicit DiscreteStream(StateSpace system) : system_(std::move(system)) {
    if (!system_.consistent() || system_.inputs() != 1 || system_.outputs() != 1)
      throw InputError("DiscreteStream: needs a consistent system of one input and one output");
    state_ = Eigen::VectorXd::Zero(system_.states());
    next_ = state_;
  }
  void reset() override { state_.setZero(); }
  double step(double in) override {
    const double out = system_.C.row(0).dot(state_) + system_.D(0, 0) * in;
    next_.noalias() = system_.A * state_;
    next_ += system_.B.col(0) * in;
    state_.swap(next_);
    return out;
  }
  std::unique_ptr<SignalStream> clone() const override { return std::make_unique<DiscreteStream>(*this); }

 private:
  StateSpace system_;
  Eigen::VectorXd state_, next_;
};

}  // namespace hystbench::robust
