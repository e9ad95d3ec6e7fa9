// Bouc-Wen oscillator: hysteretic restoring force fed back from the output
// velocity inside a mass-spring-damper (Noel & Schoukens 2016 benchmark form):
//
//   m y'' + c y' + k y + z = u,   z' = alpha y' - beta (gamma |y'| z + delta y' |z|),   nu = 1.
//
// Normalised, identifiable form with unit static gain (divide by k; y and z
// in normalised output units, z_n = z / (k y_rms)):
//
//   y''/wn^2 + 2 zeta y'/wn + y + z_n = w
//   z_n' = a y' - bg |y'| z_n - bd y' |z_n|
//
// with wn = 2 pi 10^log10_fn = sqrt(k/m), zeta = c / (2 sqrt(k m)), a = alpha/k,
// bg = beta gamma y_rms, bd = beta delta y_rms. beta alone is not
// identifiable for nu = 1 (only beta gamma and beta delta enter); nu is
// fixed at 1, which makes the loop rate-independent (z_n depends on the path
// of y, not on its speed). At a = 0, z_n stays 0: a linear oscillator.
//
// Integration: classical RK4 with `substeps` steps per sample (default 20,
// raised automatically when the oscillator is too stiff for the step), the
// input interpolated between samples with a not-a-knot cubic spline. The
// state starts at rest (y = y' = z = 0).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "framework/model/effect.hpp"
#include "framework/model/input_interpolation.hpp"

namespace hystbench {
namespace {

constexpr int kDefaultSubsteps = 20;
constexpr int kMaxSubsteps = 2000;
// A state beyond this (normalised units: the measured output has RMS 1) has
// diverged.
constexpr double kDivergence = 1e6;

class FeedbackHysteresis : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "feedback_hysteresis";
    i.summary =
        "Bouc-Wen oscillator: hysteretic restoring force driven by the output velocity "
        "inside the mass-spring-damper (nu = 1)";
    i.citation = "Noel & Schoukens, Hysteretic benchmark with a dynamic nonlinearity, 2016";
    i.stage = EffectStage::Dynamics;
    i.extends = "msd";
    i.params = {
        {"log10_fn", 0.5, 3.5, 3.5, 0, 0, "log10(Hz)",
         "natural frequency sqrt(k/m)/(2 pi) of the linear part, log10 of Hz"},
        {"zeta", 1e-3, 2.0, 0.7, 0, 0, "", "damping ratio c/(2 sqrt(k m))"},
        {"alpha", 0.0, 4.0, 0.0, 0, 0, "",
         "hysteretic stiffness relative to the linear one, alpha/k (0: no hysteresis)"},
        {"beta_gamma", -3.0, 3.0, 0.0, -1, 0, "",
         "beta*gamma: loop shape term |y'| z (physical value in 1/output unit)"},
        {"beta_delta", -3.0, 3.0, 0.0, -1, 0, "",
         "beta*delta: loop shape term y' |z| (physical value in 1/output unit)"},
    };
    i.signature =
        "a Hammerstein chain fits the low-amplitude part but the error grows with amplitude "
        "near the resonance: the hysteresis is driven by the output velocity inside the "
        "oscillator, not by the input";
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double fn = std::pow(10.0, p[0]);
    const double zeta = p[1], a = p[2], bg = p[3], bd = p[4];
    const double ts = ctx.sample_time;
    if (!std::isfinite(fn) || !(zeta > 0.0) || !std::isfinite(zeta) || !std::isfinite(a) ||
        !std::isfinite(bg) || !std::isfinite(bd) || !(ts > 0.0) || a <= -1.0)
      return false;
    const Eigen::Index n = signal.size();
    if (n == 0) return true;

    // Time in samples: w_s = wn * Ts rad per sample. z' is rate-independent,
    // so its coefficients do not change with the time unit.
    const double ws = 2.0 * std::numbers::pi * fn * ts;
    const double w2 = ws * ws, c1 = 2.0 * zeta * ws;
    // Largest eigenvalue modulus of the linearised system, bounded by
    // ws_eff (zeta + sqrt(zeta^2 + 1)); keep |lambda| h <= 1.
    const double stiff =
        ws * std::sqrt(1.0 + std::max(a, 0.0)) * (zeta + std::sqrt(zeta * zeta + 1.0));
    int sub = ctx.substeps > 0 ? ctx.substeps : kDefaultSubsteps;
    if (stiff > double(sub)) {
      if (!(stiff <= double(kMaxSubsteps))) return false;
      sub = static_cast<int>(std::ceil(stiff));
    }
    const double h = 1.0 / sub, h2 = 0.5 * h, h6 = h / 6.0;

    thread_local UniformCubicSpline spline;
    thread_local std::vector<UniformCubicSpline::Weights> weights;
    thread_local std::vector<double> wv;
    thread_local int weights_for = 0;
    spline.fit(signal);
    if (weights_for != sub) {
      weights.resize(2 * sub + 1);
      for (int j = 0; j <= 2 * sub; ++j)
        weights[j] = UniformCubicSpline::weights(double(j) / double(2 * sub));
      weights_for = sub;
    }
    wv.resize(2 * sub + 1);

    // State (y, v = dy/dsample, z).
    double y = 0.0, v = 0.0, z = 0.0;
    auto accel = [&](double w, double y_, double v_, double z_) {
      return w2 * (w - y_ - z_) - c1 * v_;
    };
    auto zdot = [&](double v_, double z_) {
      return a * v_ - bg * std::abs(v_) * z_ - bd * v_ * std::abs(z_);
    };
    signal[0] = 0.0;
    for (Eigen::Index k = 0; k + 1 < n; ++k) {
      for (int j = 0; j <= 2 * sub; ++j) wv[j] = spline.value(k, weights[j]);
      for (int i = 0; i < sub; ++i) {
        const double wa = wv[2 * i], wm = wv[2 * i + 1], wb = wv[2 * i + 2];
        const double k1y = v, k1v = accel(wa, y, v, z), k1z = zdot(v, z);
        const double y2 = y + h2 * k1y, v2 = v + h2 * k1v, z2 = z + h2 * k1z;
        const double k2y = v2, k2v = accel(wm, y2, v2, z2), k2z = zdot(v2, z2);
        const double y3 = y + h2 * k2y, v3 = v + h2 * k2v, z3 = z + h2 * k2z;
        const double k3y = v3, k3v = accel(wm, y3, v3, z3), k3z = zdot(v3, z3);
        const double y4 = y + h * k3y, v4 = v + h * k3v, z4 = z + h * k3z;
        const double k4y = v4, k4v = accel(wb, y4, v4, z4), k4z = zdot(v4, z4);
        y += h6 * (k1y + 2.0 * (k2y + k3y) + k4y);
        v += h6 * (k1v + 2.0 * (k2v + k3v) + k4v);
        z += h6 * (k1z + 2.0 * (k2z + k3z) + k4z);
      }
      // Also false for NaN.
      if (!(std::abs(y) < kDivergence && std::abs(z) < kDivergence && std::abs(v) < kDivergence))
        return false;
      signal[k + 1] = y;
    }
    return true;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::FeedbackHysteresis)
