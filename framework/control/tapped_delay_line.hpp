#pragma once
// The last `taps` samples of a signal, newest first, as one contiguous
// vector: each sample is kept twice (at i and i + taps) in a ring, so a push
// costs O(1) and recent() needs no copy. FIR filters and the FxLMS
// reference histories read it.
#include "framework/core/eigen.hpp"

namespace hystbench {

class TappedDelayLine {
 public:
  explicit TappedDelayLine(int taps = 1) { reset(taps); }
  void reset(int taps) {
    data_ = Eigen::VectorXd::Zero(2 * taps);
    head_ = 0;
  }
  void push(double v) {
    const Eigen::Index taps = data_.size() / 2;
    head_ = (head_ == 0 ? taps : head_) - 1;
    data_[head_] = v;
    data_[head_ + taps] = v;
  }
  // [x(n), x(n-1), ..., x(n-taps+1)]
  Eigen::Map<const Eigen::VectorXd> recent() const { return {data_.data() + head_, data_.size() / 2}; }

 private:
  Eigen::VectorXd data_;
  Eigen::Index head_ = 0;
};

}  // namespace hystbench
