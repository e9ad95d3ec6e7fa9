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
#include <array>
#include <cmath>
#include <numbers>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"
#include "problems/hammerstein/effects/biquad.hpp"

namespace hystbench {
namespace {

SignatureValue missing_resonance(const ResidualView& r);

class Msd : public KernelEffect<Msd, 5, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "msd";
    i.summary =
        "mass-spring-damper resonance 1/(κ²s² + 2ζκs + 1), κ = period/2π, unit static gain, "
        "bilinear";
    i.citation =
        "Hassani, Tjahjowidodo & Do, Mech. Syst. Signal Process. 49 (2014); seed Hammerstein "
        "model (docs/models.md#hammerstein-seed-model) for the bilinear discretisation";
    i.stage = EffectStage::Dynamics;
    i.params = {
        {"period", 0.0, 0.2, 0.0, 0, 0, "s",
         "natural period 1/f_n (0 = infinitely stiff: no resonance)"},
        {"zeta", 0.005, 2.0, 0.5, 0, 0, "", "damping ratio"},
    };
    i.signature =
        "the error grows with the excitation frequency, the input-residual cross-correlation is "
        "significant at positive lags and the residual spectrum peaks near the resonance";
    i.statistic = {"max corr(e, (H − 1)·ŷ) over resonances H", missing_resonance,
                   "the residual correlates with what a resonance at {f_n} Hz (ζ = {zeta}) "
                   "would add to the model output (r = {value})"};
    return i;
  }

  // c = (n0, n1, n2, a1, a2) of G = 1 - H.
  static EffectSetup setup(std::span<const double> p, double Ts, std::array<double, 5>& c) {
    const double period = p[0], zeta = p[1];
    if (!std::isfinite(period) || !std::isfinite(zeta) || period < 0.0) return EffectSetup::Invalid;
    if (period == 0.0) return EffectSetup::PassThrough;
    if (!(zeta > 0.0) || !(Ts > 0.0) || !std::isfinite(Ts)) return EffectSetup::Invalid;
    // With k = 2κ/Ts and q = 2ζk, substituting s = (2/Ts)(z−1)/(z+1) and
    // multiplying by (z+1)² gives G(z) = N(z)/D(z) with
    // N = (k² + q, −2k², k² − q), D = (k² + q + 1, 2 − 2k², k² − q + 1).
    const auto [k2, q, a0] = tustin_resonance(period / (std::numbers::pi * Ts), zeta);
    c = {(k2 + q) / a0, -2.0 * k2 / a0, (k2 - q) / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0};
    if (!std::isfinite(c[3]) || !std::isfinite(c[4]) || !std::isfinite(c[0])) return EffectSetup::Invalid;
    return EffectSetup::Run;
  }

  template <class V>
  using State = BiquadState<V>;

  // One sample: y = w − G·w, G·w from rest.
  template <class V>
  static V sample(const std::array<V, 5>& c, NoAux, State<V>& state, V w, double) {
    return w - biquad_step(c, state, w);
  }

  // The last G·w.
  template <class V>
  static V health(const std::array<V, 5>&, const State<V>& state) {
    return state.y1;
  }
};

// Natural frequencies and damping ratios tried by the signature statistic.
constexpr int kResonances = 48;
constexpr double kDampings[] = {0.05, 0.2, 0.7};

// Signature statistic: the largest |corr(e, (H − 1)·ŷ)| over resonances H =
// this effect at natural frequencies f_n log-spaced from twice the lowest
// excitation frequency (a resonance below the drive would be a slow lag, the
// province of creep) to 0.4/Ts, and damping ratios 0.05, 0.2, 0.7. (H − 1)·ŷ
// is what adding the resonance would change in the model output, the
// direction a score (Lagrange-multiplier) test looks in; a residual it
// explains is a resonance the model lacks, at the f_n quoted. A missing
// resonance leaves rate dependence in the error well below f_n too (the
// −2ζκ·dŷ/dt term), so msd and delay can both score there. About 3/√N for a
// white residual. (Ljung, System Identification, 1999, §16.6; Hassani et al.
// 2014 for the resonance.)
SignatureValue missing_resonance(const ResidualView& r) {
  const Msd msd;
  SignalContext ctx;
  ctx.sample_time = r.sample_time;
  const double f_low = 2 * r.lowest_excitation_hz, f_high = 0.4 / r.sample_time;
  if (!(f_low > 0) || !(f_high > f_low)) return {};
  SignatureValue best;
  Eigen::VectorXd change(r.y_model.size());
  for (int i = 0; i < kResonances; ++i) {
    const double f_n = f_low * std::pow(f_high / f_low, double(i) / (kResonances - 1));
    for (double zeta : kDampings) {
      change = r.y_model;
      const std::array<double, 2> p{1.0 / f_n, zeta};
      if (!msd.apply(p, ctx, change)) continue;
      const double c = correlation(r.e, change - r.y_model);
      if (std::isfinite(c) && !(std::abs(c) <= std::abs(best.value)))
        best = {c, {{"f_n", f_n}, {"zeta", zeta}}};
    }
  }
  return best;
}

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Msd)
