// Creep: slow drift towards a higher level after a change (output stage).
//
//   x_i[k] = a_i·x_i[k-1] + (1 − a_i)·y0[k],   a_i = exp(−Ts/τ_i),  τ_i = 0.1, 1, 10, 100 s
//   signal[k] += gamma · Σ_i x_i[k]
//
// y0 is the output stage's input (the output of the dynamics), so the result
// does not depend on where offset or drift sit in the list. After a step of
// size Δ the added term is gamma·Δ·Σ_i (1 − exp(−t/τ_i)), which grows by about
// gamma·Δ per decade of time from 0.1 s to 100 s: a sum of lags standing in
// for the logarithmic law y0·(1 + γ·log10(t/t0)) (Jung & Gweon 2000), with
// the time constants fixed one decade apart so that one parameter (the
// creep per decade) describes it and a 10-60 s staircase record identifies
// it. The lags are exact discretisations of first-order lags (the step
// response is sampled exactly), starting from rest (x_i[-1] = 0).
// Neutral gamma = 0. Units: gamma is a ratio (y per y per decade).
#include <array>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

constexpr std::array<double, 4> kTimeConstants{0.1, 1.0, 10.0, 100.0};  // s

// Signature statistic: corr(e, u_slow), u_slow = u through a first-order lag
// whose time constant is one period of the lowest excitation frequency. Creep
// is a slow approach to the level the input was moved to, so the residual
// follows a slowly filtered input; faster errors (dynamics, hysteresis) are
// averaged out by the lag. (Jung & Gweon, Rev. Sci. Instrum. 71, 2000.)
SignatureValue slow_input_correlation(const ResidualView& r) {
  const double tau = 1.0 / r.lowest_excitation_hz;
  if (!(tau > 0) || !std::isfinite(tau)) return {};
  return {correlation(r.e, first_order_lag(r.u, tau, r.sample_time)), {{"tau", tau}}};
}

class Creep : public KernelEffect<Creep, 1, EffectDrive::StageInput> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "creep";
    i.summary =
        "creep: gamma per decade of time, as first-order lags at 0.1, 1, 10 and 100 s driven by "
        "the output";
    i.citation =
        "Jung & Gweon, Rev. Sci. Instrum. 71 (2000) (creep of piezo actuators); "
        "Janocha & Kuhnen, Sens. Actuators A 79 (2000)";
    i.stage = EffectStage::Output;
    i.params = {{"gamma", -0.5, 0.5, 0.0, 0, 0, "",
                 "creep per decade of time, relative to the instantaneous response"}};
    i.signature =
        "the residual drifts slowly and monotonically after level changes, has power below the "
        "lowest excitation frequency and correlates with the low-pass-filtered input";
    i.statistic = {"corr(e, lagged u)", slow_input_correlation,
                   "the residual correlates with the input through a first-order lag of {tau} s, "
                   "one period of the slowest excitation (r = {value})"};
    // Without a held input level, creep's slow approach is a trend (drift)
    // or a constant (offset) over a short record.
    i.rivals = {{"drift", ExcitationNeed::HeldLevel}, {"offset", ExcitationNeed::HeldLevel}};
    return i;
  }

  // c = (gamma).
  static EffectSetup setup(std::span<const double> p, double Ts, std::array<double, 1>& c) {
    const EffectSetup s = gain_like_setup(p, c);
    if (s != EffectSetup::Run) return s;
    return Ts > 0.0 && std::isfinite(Ts) ? EffectSetup::Run : EffectSetup::Invalid;
  }

  // x_i[k] = a_i·x_i[k-1] + b_i·y0[k] for the sample time Ts, the same for
  // every lane.
  struct Lags {
    std::array<double, 4> a, b;
  };
  static Lags aux(double Ts) {
    Lags l{};
    for (std::size_t i = 0; i < l.a.size(); ++i) {
      l.a[i] = std::exp(-Ts / kTimeConstants[i]);
      l.b[i] = -std::expm1(-Ts / kTimeConstants[i]);  // 1 − a, accurately
    }
    return l;
  }

  // The lags at rest.
  template <class V>
  struct State {
    V x0{}, x1{}, x2{}, x3{};
  };

  // One sample.
  template <class V>
  static V sample(const std::array<V, 1>& c, const Lags& l, State<V>& x, V signal, V y0) {
    x.x0 = l.a[0] * x.x0 + l.b[0] * y0;
    x.x1 = l.a[1] * x.x1 + l.b[1] * y0;
    x.x2 = l.a[2] * x.x2 + l.b[2] * y0;
    x.x3 = l.a[3] * x.x3 + l.b[3] * y0;
    return signal + c[0] * ((x.x0 + x.x1) + (x.x2 + x.x3));
  }

  // The sum of the lag states.
  template <class V>
  static V health(const std::array<V, 1>&, const State<V>& x) {
    return x.x0 + x.x1 + x.x2 + x.x3;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Creep)
