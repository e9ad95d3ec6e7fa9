#include "framework/control/modal_stream.hpp"

#include <cmath>

namespace hystbench {

std::complex<double> modal_response(const std::vector<Mode>& modes, double hz) {
  const double w = 2.0 * M_PI * hz;
  std::complex<double> sum = 0.0;
  for (const Mode& m : modes)
    sum += m.output * m.input /
           std::complex<double>(m.omega * m.omega - w * w, 2.0 * m.zeta * m.omega * w);
  return sum;
}

ModalStream::ModalStream(const std::vector<Mode>& modes, double T, int delay_samples)
    : delay_samples_(delay_samples) {
  for (const Mode& m : modes) {
    const double wd = m.omega * std::sqrt(1.0 - m.zeta * m.zeta);
    const double E = std::exp(-m.zeta * m.omega * T), C = std::cos(wd * T), S = std::sin(wd * T);
    Discrete d;
    d.p11 = E * (C + m.zeta * m.omega / wd * S);
    d.p12 = E * S / wd;
    d.p21 = -m.omega * m.omega * E * S / wd;
    d.p22 = E * (C - m.zeta * m.omega / wd * S);
    // The exact integral of the transition over one hold interval.
    d.g1 = m.input * (-(2.0 * m.zeta / m.omega) * d.p12 - (d.p22 - 1.0) / (m.omega * m.omega));
    d.g2 = m.input * d.p12;
    d.c = m.output;
    modes_.push_back(d);
  }
  reset();
}

void ModalStream::reset() {
  q_.assign(modes_.size(), 0.0);
  v_.assign(modes_.size(), 0.0);
  delay_.assign(delay_samples_, 0.0);
}

double ModalStream::step(double u) {
  double y = 0.0;
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    const Discrete& d = modes_[i];
    y += d.c * q_[i];
    const double q = d.p11 * q_[i] + d.p12 * v_[i] + d.g1 * u;
    v_[i] = d.p21 * q_[i] + d.p22 * v_[i] + d.g2 * u;
    q_[i] = q;
  }
  if (delay_samples_ == 0) return y;
  delay_.push_back(y);
  const double out = delay_.front();
  delay_.pop_front();
  return out;
}

std::unique_ptr<SignalStream> ModalStream::clone() const {
  return std::make_unique<ModalStream>(*this);
}

}  // namespace hystbench
