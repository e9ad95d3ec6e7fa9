#pragma once
// A causal single-input single-output system run one sample at a time: a
// model streamed sample by sample (StreamingModel), and later a plant path,
// a filter or a secondary-path estimate inside a control loop.
#include <memory>

namespace hystbench {

class SignalStream {
 public:
  virtual ~SignalStream() = default;
  // Back to the initial state (at rest).
  virtual void reset() = 0;
  // Output at sample k from the input at k; samples arrive in order.
  virtual double step(double in) = 0;
  // An independent copy in the current state.
  virtual std::unique_ptr<SignalStream> clone() const = 0;
};

}  // namespace hystbench
