// Proposed from data by `hystbench propose`: the term x³ at the dynamics stage,
// from the residual of the model hysteresis,asymmetry,msd,arx fitted to data.csv. It explained 93 %
// of what that fit left; proposed coefficient -0.00743421 ± 2.2e-05 (normalised units).
//
//   signal[k] += c·x³,   x' = (x[k] − x[k−1]) / Ts,   x'[0] = 0
//
// with x the resonance's own output (the force depends on the output it drives). c = 0 leaves the signal unchanged.
// Build: see docs/plugins.md (out of the tree: a shared library).
#include <cmath>
#include <algorithm>
#include <array>
#include <numbers>

#include "problems/hammerstein/effects/biquad.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

// |a|^power, times sign(a) when odd.
double factor(double a, int power, bool odd) {
  double m = 1.0;
  for (int i = 0; i < power; ++i) m *= std::abs(a);
  if (odd && power > 0) m = a < 0 ? -m : (a > 0 ? m : 0.0);
  return m;
}

double term(double a, double a_rate) {
  return factor(a, 3, true) * factor(a_rate, 0, false);
}

// Residual signature: the residual follows the term, built from the model output.
hystbench::SignatureValue term_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd& a = r.y_model;
  Eigen::VectorXd phi(a.size());
  double previous = a.size() ? a[0] : 0.0;  // no rate before the record
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    phi[k] = term(a[k], (a[k] - previous) / r.sample_time);
    previous = a[k];
  }
  return {hystbench::correlation(r.e, phi)};
}

class ProposedTerm : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "proposed_term";
    i.summary = "proposed from data: c·x³ at the dynamics stage";
    i.citation = "proposed from data by hystbench propose (data.csv, residual of hysteresis,asymmetry,msd,arx)";
    i.stage = hystbench::EffectStage::Dynamics;
    i.extends = "msd";
    i.params = {{"period", 0, 0.20000000000000001, 0, 0, 0, "s", "natural period 1/f_n (0 = infinitely stiff: no resonance)"},
                {"zeta", 0.0050000000000000001, 2, 0.5, 0, 0, "", "damping ratio"},
                {"c", -0.074342103949181698, 0.074342103949181698, 0, -2, 0, "", "coefficient of the proposed term"}};
    i.signature = "the residual follows x³";
    i.statistic = {"corr(e, x³)", term_correlation, "the residual follows x³ (r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double period = p[0], zeta = p[1], c = p[2], Ts = ctx.sample_time;
    if (!std::isfinite(period) || !std::isfinite(zeta) || !std::isfinite(c) || period < 0.0) return false;
    if (!(Ts > 0.0) || !std::isfinite(Ts)) return false;
    std::array<double, 5> g{};  // G = 1 − H, as msd
    const bool resonant = period > 0.0;
    if (resonant) {
      if (!(zeta > 0.0)) return false;
      const auto [k2, q, a0] = hystbench::tustin_resonance(period / (std::numbers::pi * Ts), zeta);
      g = {(k2 + q) / a0, -2.0 * k2 / a0, (k2 - q) / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0};
      if (!std::isfinite(g[3]) || !std::isfinite(g[4]) || !std::isfinite(g[0])) return false;
    }
    hystbench::BiquadState<double> state{};
    double x1 = 0.0;  // the output one sample earlier
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      const double w = signal[k];
      // The output for a given input of the resonance at this sample, its state left as it is.
      const auto output = [&](double input) {
        if (!resonant) return input;
        const double gw = ((g[0] * input + g[1] * state.w1) + (g[2] * state.w2 - g[4] * state.y2)) - g[3] * state.y1;
        return input - gw;
      };
      double force = 0.0;
      if (c != 0.0) {
        // The force depends on the output it drives: x = output(w + c·term(x, (x − x1)/Ts)),
        // solved by Newton's method from the previous output.
        const auto residual = [&](double x) { return x - output(w + c * term(x, (x - x1) / Ts)); };
        double x = x1;
        bool converged = false;
        for (int i = 0; i < 12 && !converged; ++i) {
          const double f = residual(x), h = 1e-7 * std::max(1.0, std::abs(x));
          const double slope = (residual(x + h) - f) / h;
          if (!std::isfinite(f) || !std::isfinite(slope) || slope == 0.0) return false;
          const double step = f / slope;
          x -= step;
          converged = std::abs(step) <= 1e-12 * std::max(1.0, std::abs(x));
        }
        if (!converged) return false;  // no output consistent with its force: diverging
        force = c * term(x, (x - x1) / Ts);
      }
      const double input = w + force;
      const double x = resonant ? input - hystbench::biquad_step(g, state, input) : input;
      signal[k] = x;
      x1 = x;
    }
    return signal.allFinite();
  }
};
}  // namespace

HYSTBENCH_EFFECT(ProposedTerm)
