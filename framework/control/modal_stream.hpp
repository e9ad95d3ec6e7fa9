#pragma once
// A sum of lightly damped second-order modes, y = sum_i c_i q_i with
// q_i'' + 2 zeta_i w_i q_i' + w_i^2 q_i = b_i u, discretised exactly under a
// zero-order hold on u (docs/control.md#plant): the output at sample n
// depends on u up to n - 1, then an optional pure delay of whole samples.
#include <complex>
#include <deque>
#include <vector>

#include "framework/model/signal_stream.hpp"

namespace hystbench {

struct Mode {
  double omega;   // natural frequency, rad/s
  double zeta;    // damping ratio (0 < zeta < 1)
  double input;   // b_i, including any gain
  double output;  // c_i
};

// Continuous-time response sum_i c_i b_i / (w_i^2 - w^2 + 2 j zeta_i w_i w).
std::complex<double> modal_response(const std::vector<Mode>& modes, double hz);

class ModalStream final : public SignalStream {
 public:
  ModalStream(const std::vector<Mode>& modes, double sample_time, int delay_samples = 0);

  void reset() override;
  double step(double u) override;
  std::unique_ptr<SignalStream> clone() const override;

 private:
  struct Discrete {
    double p11, p12, p21, p22;  // state transition of [q, q']
    double g1, g2;              // input gains (times b_i)
    double c;
  };
  std::vector<Discrete> modes_;
  std::vector<double> q_, v_;  // displacement and velocity per mode
  std::deque<double> delay_;   // the last outputs, oldest first
  int delay_samples_;
};

}  // namespace hystbench
