// Mass-spring-damper resonance with unit static gain (dynamics stage).
//
//   H(s) = 1 / (κ²s² + 2ζκs + 1),   κ = 1/ω_n = period / (2π)
//
// discretised bilinearly (s = (2/Ts)(z−1)/(z+1)) like the seed model's MSD
// block, from rest (w[k<0] = 0). Parameters are the natural period
// 1/f_n and the damping ratio ζ instead of mass, damping and stiffness: the
// static gain is fixed to 1 (the model's gain carries it), so no product of
// parameters is unidentifiable.
//
// Neutral: period = 0, an infinitely stiff spring: H = 1 exactly. The
// natural period rather than the frequency is the parameter so that the
// pass-through is a point inside the box (a frequency would need +∞). The
// block is computed in complementary form, y = w − G·w with
// G = 1 − H = (κ²s² + 2ζκs)/(κ²s² + 2ζκs + 1): near the neutral value G·w is
// small and its rounding errors are small with it, whereas the direct form
// would cancel a nearly double pole at z = −1 against the double zero there.
//
// Bilinear discretisation keeps the pole pair inside the unit circle for any
// period > 0 and ζ > 0; ζ ≤ 0 (undamped or unstable) or a negative period
// makes apply false.
#include <cmath>
#include <numbers>

#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Msd : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "msd";
    i.summary =
        "mass-spring-damper resonance 1/(κ²s² + 2ζκs + 1), κ = period/2π, unit static gain, "
        "bilinear";
    i.citation =
        "Hassani, Tjahjowidodo & Do, Mech. Syst. Signal Process. 49 (2014); seed Hammerstein "
        "model (DESIGN.md §3) for the bilinear discretisation";
    i.stage = EffectStage::Dynamics;
    i.params = {
        {"period", 0.0, 0.2, 0.0, 0, 0, "s",
         "natural period 1/f_n (0 = infinitely stiff: no resonance)"},
        {"zeta", 0.005, 2.0, 0.5, 0, 0, "", "damping ratio"},
    };
    i.signature =
        "the error grows with the excitation frequency, the input-residual cross-correlation is "
        "significant at positive lags and the residual spectrum peaks near the resonance";
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double period = p[0], zeta = p[1];
    if (!std::isfinite(period) || !std::isfinite(zeta) || period < 0.0) return false;
    if (period == 0.0) return true;
    if (!(zeta > 0.0) || !(ctx.sample_time > 0.0) || !std::isfinite(ctx.sample_time))
      return false;
    // With c = 2κ/Ts and q = 2ζc, substituting s = (2/Ts)(z−1)/(z+1) and
    // multiplying by (z+1)² gives G(z) = N(z)/D(z) with
    // N = (c² + q, −2c², c² − q), D = (c² + q + 1, 2 − 2c², c² − q + 1).
    const double c = period / (std::numbers::pi * ctx.sample_time);
    const double c2 = c * c, q = 2.0 * zeta * c;
    const double a0 = c2 + q + 1.0;
    const double n0 = (c2 + q) / a0, n1 = -2.0 * c2 / a0, n2 = (c2 - q) / a0;
    const double a1 = (2.0 - 2.0 * c2) / a0, a2 = (c2 - q + 1.0) / a0;
    if (!std::isfinite(a1) || !std::isfinite(a2) || !std::isfinite(n0)) return false;
    double* s = signal.data();
    double w1 = 0.0, w2 = 0.0, e1 = 0.0, e2 = 0.0;
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      const double w = s[k];
      const double e = ((n0 * w + n1 * w1) + (n2 * w2 - a2 * e2)) - a1 * e1;
      s[k] = w - e;
      w2 = w1;
      w1 = w;
      e2 = e1;
      e1 = e;
    }
    return std::isfinite(e1);
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Msd)
