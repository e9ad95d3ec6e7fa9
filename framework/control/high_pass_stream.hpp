#pragma once
// A first-order high-pass (an AC-coupled sensor) after another stream:
// H(s) = s / (s + wc), sampled with its pole matched, z = exp(-wc T):
// y(n) = a (y(n-1) + x(n) - x(n-1)), a = exp(-wc T). It removes a static
// offset (e.g. the bending an asymmetric actuator adds), which no tonal
// controller can act on and which is not vibration.
#include <cmath>
#include <complex>
#include <memory>

#include "framework/model/signal_stream.hpp"

namespace hystbench {

class HighPassStream final : public SignalStream {
 public:
  HighPassStream(std::unique_ptr<SignalStream> inner, double corner_hz, double sample_time)
      : inner_(std::move(inner)), a_(std::exp(-2.0 * M_PI * corner_hz * sample_time)) {}
  HighPassStream(const HighPassStream& o) : inner_(o.inner_->clone()), a_(o.a_) {}

  void reset() override {
    inner_->reset();
    last_in_ = last_out_ = 0.0;
  }
  double step(double u) override {
    const double x = inner_->step(u);
    last_out_ = a_ * (last_out_ + x - last_in_);
    last_in_ = x;
    return last_out_;
  }
  std::unique_ptr<SignalStream> clone() const override {
    return std::make_unique<HighPassStream>(*this);
  }

  // Continuous-time response s / (s + wc) at `hz`.
  static std::complex<double> response(double corner_hz, double hz) {
    const std::complex<double> s(0.0, hz);
    return corner_hz > 0.0 ? s / (s + corner_hz) : 1.0;
  }

 private:
  std::unique_ptr<SignalStream> inner_;
  double a_;
  double last_in_ = 0.0, last_out_ = 0.0;
};

}  // namespace hystbench
