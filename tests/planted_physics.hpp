#pragma once
// Actuators with physics the effect catalog does not hold, simulated here
// for the purpose (no catalog effect is used):
//
//   static part   w = gain·u·(1 + rate_gain·|u'|)          a gain that grows with the drive rate
//                       ·(1 + gain_drift·t)                and one that drifts with time (heating)
//                   + play_gain·P(u)                       and a play operator beside the gain: P of
//                                                          radius play_radius·max|u|, from 0, widened
//                                                          by (1 + play_width_rate·|u'|): a loop that
//                                                          grows with the drive rate
//   dynamics      x''/ω² + 2ζx'/ω + x + cubic·x³           a stiffness that grows with amplitude,
//                   + drive_stiffness·|w|·x                and one that grows with the drive,
//                   + quadratic_damping·x'·|x'|            a drag that grows with the speed
//                   + coulomb·tanh(x'/kStick) = w          and dry (Coulomb) friction, its jump at
//                                                          x' = 0 smoothed over kStick for the RK4
//   output        y = x + root_gain·sign(x)·√|x| + noise  a sensor law steeper than linear near 0
//
// ω = 2π/period. The ODE is integrated by RK4 with 20 sub-steps per sample,
// the drive linear between samples; u' is the backward difference of u.
// The drive is a multisine whose amplitude rises and falls, so that the
// record holds small and large amplitudes at every frequency.
#include "framework/core/eigen.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "framework/io/measurement.hpp"

namespace hystbench::planted {

struct System {
  double gain = 1.0;
  double rate_gain = 0.0;  // s (per unit of |u'|, u' in units of u per s)
  double gain_drift = 0.0; // per s
  double period = 0.02;    // s
  double zeta = 0.15;
  double cubic = 0.0;      // per unit of x²
  double play_gain = 0.0;
  double play_radius = 0.25;      // share of max |u|
  double play_width_rate = 0.0;   // s (the radius grows by this per unit of |u'|)
  double drive_stiffness = 0.0;   // per unit of |w|
  double quadratic_damping = 0.0; // s² per unit of x (x' in units of y per s)
  double coulomb = 0.0;           // dry friction force, units of y (as a static displacement)
  double root_gain = 0.0;  // units of y^(1/2)
  double noise = 0.01;     // sd, units of y
};

// n samples at sample time ts: 12 sines log-spaced from 1 Hz to 0.08/ts
// with fixed random phases, under an envelope 0.3 + 0.7·sin²(πt/T).
inline Eigen::VectorXd multisine(Eigen::Index n, double ts) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  constexpr int kSines = 12;
  const double f0 = 1.0, f1 = 0.08 / ts, T = double(n) * ts;
  std::array<double, kSines> f{}, p{};
  for (int i = 0; i < kSines; ++i) {
    f[std::size_t(i)] = f0 * std::pow(f1 / f0, double(i) / (kSines - 1));
    p[std::size_t(i)] = phase(rng);
  }
  Eigen::VectorXd u(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = double(k) * ts, s = std::sin(M_PI * t / T);
    double sum = 0.0;
    for (int i = 0; i < kSines; ++i) sum += std::sin(2.0 * M_PI * f[std::size_t(i)] * t + p[std::size_t(i)]);
    u[k] = (0.3 + 0.7 * s * s) * sum / std::sqrt(double(kSines) / 2.0);
  }
  return u;
}

// y for the drive u (from rest), with noise from `seed`.
inline Measurement simulate(const System& s, const Eigen::VectorXd& u, double ts, unsigned seed = 7) {
  const Eigen::Index n = u.size();
  Eigen::VectorXd w(n);
  double previous = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double rate = (u[k] - previous) / ts;
    previous = u[k];
    w[k] = s.gain * u[k] * (1.0 + s.rate_gain * std::abs(rate)) * (1.0 + s.gain_drift * double(k) * ts);
  }
  if (s.play_gain != 0.0) {
    const double r0 = s.play_radius * u.cwiseAbs().maxCoeff();
    double p = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double rate = k > 0 ? (u[k] - u[k - 1]) / ts : 0.0;
      const double r = r0 * (1.0 + s.play_width_rate * std::abs(rate));
      p = std::min(u[k] + r, std::max(u[k] - r, p));
      w[k] += s.play_gain * p;
    }
  }
  const double omega = 2.0 * M_PI / s.period;
  // The speed over which the friction force turns: small beside the record's
  // speeds (x' of order 100 per s), wide enough for 20 RK4 sub-steps a sample.
  constexpr double kStick = 0.5;
  const auto accel = [&](double x, double v, double drive) {
    return omega * omega *
               (drive - x - s.cubic * x * x * x - s.drive_stiffness * std::abs(drive) * x -
                s.quadratic_damping * v * std::abs(v) - s.coulomb * std::tanh(v / kStick)) -
           2.0 * s.zeta * omega * v;
  };
  constexpr int kSub = 20;
  const double h = ts / kSub;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, s.noise);
  Measurement m;
  m.t.resize(n);
  m.y.resize(n);
  m.u = u;
  m.sample_time = ts;
  double x = 0.0, v = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    m.t[k] = double(k) * ts;
    m.y[k] = x + s.root_gain * std::copysign(std::sqrt(std::abs(x)), x) + noise(rng);
    if (k + 1 == n) break;
    for (int i = 0; i < kSub; ++i) {
      const auto drive = [&](double frac) { return w[k] + (w[k + 1] - w[k]) * (double(i) + frac) / kSub; };
      const double k1x = v, k1v = accel(x, v, drive(0.0));
      const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v, drive(0.5));
      const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v, drive(0.5));
      const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v, drive(1.0));
      x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
      v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    }
  }
  return m;
}

}  // namespace hystbench::planted
