#include "framework/tracking/hinf_design.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "framework/core/error.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/hinf_synthesis.hpp"
#include "framework/robust/linear_system.hpp"
#include "framework/robust/mixed_sensitivity.hpp"
#include "framework/robust/model_reduction.hpp"
#include "framework/robust/tustin.hpp"

namespace hystbench {
namespace {

using robust::StateSpace;
using robust::TimeDomain;

ControllerCheck check(const ControllerDesign& d, const StateSpace& K, const StateSpace& Kd,
                      const StateSpace& discrete_dynamics, const StateSpace& wa) {
  ControllerCheck c;
  const StateSpace closed = robust::lower_lft(d.plant, K, 1, 1);
  c.stable = robust::is_stable(closed, TimeDomain::Continuous);
  c.norm = robust::hinf_norm(closed, TimeDomain::Continuous).norm;
  c.edges_stable = robust::feedback_stability_margin(robust::parallel(d.continuous_dynamics, wa), K,
                                                     TimeDomain::Continuous) < 0.0 &&
                   robust::feedback_stability_margin(robust::difference(d.continuous_dynamics, wa), K,
                                                     TimeDomain::Continuous) < 0.0;
  c.spectral_radius = robust::feedback_stability_margin(discrete_dynamics, Kd, TimeDomain::Discrete);
  return c;
}

// |K(j2πf)| at its largest from 0.01 Hz to 1 MHz: the peak gain of a
// controller the H∞ norm calls infinite because it is unstable.
double peak_gain(const StateSpace& K) {
  double peak = 0.0;
  for (int i = 0; i <= 400; ++i)
    peak = std::max(peak, std::abs(robust::frequency_response_hz(K, std::pow(10.0, -2.0 + 8.0 * i / 400.0))));
  return peak;
}

robust::Reduction reduce(const StateSpace& K, const DesignOptions& o, std::string& method) {
  if (o.reduction == "stochastic") {
    // AB09HD needs D of full rank or BETA > 0; the central controller is
    // strictly proper, and BETA of 1e-3 of its gain keeps the error relative.
    double gain = robust::hinf_norm(K, TimeDomain::Continuous).norm;
    if (!std::isfinite(gain)) gain = peak_gain(K);
    const double beta = K.D.isZero() ? 1e-3 * gain : 0.0;
    try {
      method = "stochastic";
      return robust::stochastic_truncation(K, TimeDomain::Continuous, o.reduced_order, beta);
    } catch (const InputError& e) {
      method = std::string("balanced (stochastic truncation failed: ") + e.what() + ")";
    }
  } else {
    method = "balanced";
  }
  return robust::balanced_truncation(K, TimeDomain::Continuous, o.reduced_order);
}

double relative_error(const StateSpace& K, const StateSpace& Kr) {
  double worst = 0.0;
  for (int i = 0; i <= 300; ++i) {
    const double hz = std::pow(10.0, 3.0 * i / 300.0);  // 1 Hz to 1 kHz
    const auto full = robust::frequency_response_hz(K, hz);
    const double error = std::abs(full - robust::frequency_response_hz(Kr, hz));
    if (std::abs(full) > 0.0) worst = std::max(worst, error / std::abs(full));
  }
  return worst;
}

}  // namespace

StateSpace reference_dynamics() {
  const double wn = 2.0 * std::numbers::pi * 1260.0, zeta = 0.6;
  return robust::transfer_function({wn * wn}, {1.0, 2.0 * zeta * wn, wn * wn});
}

ControllerDesign reference_design(const DesignOptions& options) {
  const double ts = 1e-4;
  const StateSpace l = reference_dynamics();
  return design_controller(l, robust::zero_order_hold(l, ts), ts, seed_uncertainty_weight(), options);
}

StateSpace PerformanceWeight::weight() const {
  const double wb = 2.0 * std::numbers::pi * bandwidth_hz;
  return robust::transfer_function({1.0 / peak, wb}, {1.0, wb * low_frequency_error});
}

ControllerDesign design_controller(const NominalDynamics& nominal, const UncertaintyWeight& wa,
                                   const DesignOptions& o) {
  return design_controller(robust::inverse_tustin(nominal.discrete, nominal.sample_time), nominal.discrete,
                           nominal.sample_time, wa, o);
}

ControllerDesign design_controller(const StateSpace& continuous_dynamics, const StateSpace& discrete_dynamics,
                                   double sample_time, const UncertaintyWeight& wa, const DesignOptions& o) {
  if (o.reduced_order < 1) throw InputError("design: the reduced order must be at least 1");
  ControllerDesign d;
  d.continuous_dynamics = continuous_dynamics;
  d.plant = robust::mixed_sensitivity_plant(d.continuous_dynamics,
                                            {o.performance.weight(), wa.weight, std::nullopt});
  robust::HinfOptions h;
  h.backoff = o.backoff;
  const robust::HinfController k = robust::hinf_synthesis(d.plant, 1, 1, h);
  d.gamma_min = k.gamma_min;
  d.gamma = k.gamma;
  d.full = k.controller;
  const robust::Reduction r = reduce(d.full, o, d.reduction);
  d.reduced = r.reduced;
  d.hankel = r.hankel;
  d.reduction_bound = r.error_bound;
  d.reduction_error = robust::hinf_norm(robust::difference(d.full, d.reduced), TimeDomain::Continuous).norm;
  d.reduction_relative_error = relative_error(d.full, d.reduced);
  d.full_discrete = robust::tustin(d.full, sample_time);
  d.reduced_discrete = robust::tustin(d.reduced, sample_time);
  d.full_check = check(d, d.full, d.full_discrete, discrete_dynamics, wa.weight);
  d.reduced_check = check(d, d.reduced, d.reduced_discrete, discrete_dynamics, wa.weight);
  return d;
}

}  // namespace hystbench
