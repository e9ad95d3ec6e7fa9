// Thermal drift: the actuator warms up with the power it is driven at and expands.
//
//   P[k] = a·P[k-1] + (1 - a)·v[k]²,   a = exp(-Ts/tau),   P[-1] = 0
//   signal[k] += k·P[k]
//
// P is the drive power v² through a first-order thermal lag (the temperature
// rise of a lumped heat capacity); k·P is added beside gain·v, so the thermal
// expansion passes through the dynamics like any other displacement.
// Neutral k = 0. Units: k in y/u² (y_power 1, u_power -2), tau in s.
#include <cmath>

#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {
// Residual signature: the residual follows the drive power through a slow
// lag (3 s, inside the range of tau); about ±1/√N for a white residual.
hystbench::SignatureValue lagged_power_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd power = r.u.cwiseAbs2();
  return {hystbench::correlation(r.e, hystbench::first_order_lag(power, 3.0, r.sample_time))};
}

class ThermalDrift : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "thermal_drift";
    i.summary = "thermal expansion k·P, P = drive power v² through a first-order thermal lag";
    i.citation =
        "Senousy et al., Smart Mater. Struct. 18 (2009) 045008 (self-heating of piezo stacks)";
    i.stage = hystbench::EffectStage::Nonlinearity;
    i.params = {{"k", -5.0, 5.0, 0.0, 1, -2, "", "expansion per unit of lagged drive power"},
                {"tau", 0.1, 30.0, 3.0, 0, 0, "s", "thermal time constant"}};
    i.signature =
        "the residual rises slowly while the drive is large, whatever its sign, and decays "
        "exponentially once the drive stops";
    i.statistic = {"corr(e, lagged u²)", lagged_power_correlation,
                   "the residual follows the drive power u² through a 3 s lag (r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double k = p[0], tau = p[1];
    if (!std::isfinite(k) || !std::isfinite(tau)) return false;
    if (k == 0.0) return true;  // neutral: the signal is left exactly as it was
    if (!(tau > 0.0) || !(ctx.sample_time > 0.0)) return false;
    if (!ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    const double a = std::exp(-ctx.sample_time / tau), b = -std::expm1(-ctx.sample_time / tau);
    const Eigen::VectorXd& v = *ctx.stage_input;
    double power = 0.0;
    for (Eigen::Index n = 0; n < signal.size(); ++n) {
      power = a * power + b * v[n] * v[n];
      signal[n] += k * power;
    }
    return std::isfinite(power);
  }
};
}  // namespace

HYSTBENCH_EFFECT(ThermalDrift)
