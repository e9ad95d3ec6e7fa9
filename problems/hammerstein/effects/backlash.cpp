// Backlash (play operator) on the input (input stage).
//
//   F[k] = max(v[k] − r, min(v[k] + r, F[k-1])),   signal[k] = F[k]
//
// Initial state F[-1] = 0: the chain starts at rest with zero input
// (docs/models.md#hammerstein-seed-model), so a record starting at |v[0]| > r starts on a branch.
// Neutral r = 0 (F = v exactly). A negative width is meaningless: apply
// returns false. Units: r in u.
#include <algorithm>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, sign(Δu)). A play of half-width r makes the
// output lag the input by r in the direction of motion, so the residual jumps
// with the direction at every reversal: a square wave in sign(Δu).
// (Krasnosel'skii & Pokrovskii 1989, play operator; Ljung 1999 §16.6.)
SignatureValue direction_correlation(const ResidualView& r) {
  return {correlation(r.e, direction_of_motion(r.u))};
}

class Backlash : public KernelEffect<Backlash, 1, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "backlash";
    i.summary = "play operator of half-width r on the input (dead band at reversals)";
    i.citation =
        "Krasnosel'skii & Pokrovskii, Systems with Hysteresis, Springer 1989 (play operator); "
        "Janocha & Kuhnen, Sens. Actuators A 79 (2000)";
    i.stage = EffectStage::Input;
    // At r = 0.3 input RMS the play already swallows a third of a sine's
    // stroke; wider bounds only give the global search a basin of dead-band
    // models far from any real actuator (seen on the hidden-backlash case).
    i.params = {{"r", 0.0, 0.3, 0.0, 0, 1, "", "half-width of the play (0 = no backlash)"}};
    i.signature =
        "the error sits at the reversal points where du/dt changes sign and the residual "
        "correlates with sign(du/dt)";
    i.statistic = {"corr(e, sign Δu)", direction_correlation,
                   "the residual correlates with the direction of motion sign(Δu) (r = {value})"};
    return i;
  }

  // c = (r).
  static EffectSetup setup(std::span<const double> p, double /*Ts*/, std::array<double, 1>& c) {
    c = {p[0]};
    if (!std::isfinite(c[0]) || c[0] < 0.0) return EffectSetup::Invalid;
    return c[0] == 0.0 ? EffectSetup::PassThrough : EffectSetup::Run;
  }

  template <class V>
  struct State {
    V f{};  // F[-1] = 0
  };

  // One sample: F = max(v − r, min(v + r, F)), with the comparisons of
  // std::min and std::max, so that a lane gives what one candidate does.
  template <class V>
  static V sample(const std::array<V, 1>& c, NoAux, State<V>& state, V v, double) {
    const V upper = v + c[0], lower = v - c[0];
    const V below = state.f < upper ? state.f : upper;  // std::min(upper, f)
    state.f = lower < below ? below : lower;             // std::max(lower, below)
    return state.f;
  }

  template <class V>
  static V health(const std::array<V, 1>&, const State<V>& state) {
    return state.f;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Backlash)
