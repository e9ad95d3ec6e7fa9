// Rate-independent Bouc-Wen hysteresis (nonlinearity stage).
//
//   h[k] = h[k-1] + A·Δv[k] − β·|Δv[k]|·h[k-1] − γ·Δv[k]·|h[k-1]|,   Δv[k] = v[k] − v[k-1]
//   signal[k] −= h[k]
//
// v is the stage input (the normalised drive after the input effects), so
// the loop is driven by the drive, as h is by u in the seed model's
// h1 = d1·u + d2·u² − h (docs/models.md#hammerstein-seed-model). A stands for
// the seed's α·L: the two enter only as a product, so one parameter keeps the
// direction identifiable.
// The loop's branch slopes are set by A, its width saturates at about
// A/(β+γ); none of them can be traded against the model's gain.
//
// Initial state: at rest, v[-1] = 0 and h[-1] = 0, as in the seed model.
// Neutral: A = 0 keeps h ≡ 0 whatever β and γ are.
// Units: A in y/u; β and γ in 1/u (β·|Δv| and γ·Δv are pure numbers).
// A diverging loop (large β·|Δv| with a violent drive) makes apply false.
#include <array>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"
#include "problems/hammerstein/bouc_wen.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, u − play_r(u)), the stop operator of the input
// at the width r (1/16 .. 1/2 of the input's half range) where it is largest.
// A missing rate-independent loop leaves a residual that switches with the
// direction of motion but, unlike backlash's square wave sign(Δu), turns over
// gradually after each reversal and saturates: the shape of a stop operator,
// the building block of Prandtl–Ishlinskii hysteresis (Krasnosel'skii &
// Pokrovskii, Systems with Hysteresis, 1989). About ±1/√N when white.
SignatureValue input_loop_correlation(const ResidualView& r) {
  const LoopCorrelation loop = loop_correlation(r.e, r.u);
  return {loop.correlation, {{"width", loop.width}}};
}

class Hysteresis : public KernelEffect<Hysteresis, 3, EffectDrive::StageInput> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "hysteresis";
    i.summary = "rate-independent Bouc-Wen hysteresis loop driven by the input increments";
    i.citation =
        "Bouc, Proc. 4th Conf. Nonlinear Oscillations, 1967; Wen, J. Eng. Mech. 102 (1976); "
        "increment form as in the seed Hammerstein model (docs/models.md#hammerstein-seed-model)";
    i.stage = EffectStage::Nonlinearity;
    i.params = {
        {"A", -10.0, 10.0, 0.0, 1, -1, "",
         "loop amplitude: h grows by A·Δv (0 = no hysteresis; the seed's α·L)"},
        {"beta", 0.0, 10.0, 1.0, 0, -1, "", "Bouc-Wen β: decay of h with |Δv| (loop width)"},
        {"gamma", -10.0, 10.0, 0.0, 0, -1, "", "Bouc-Wen γ: loop shape (fat vs. slim ends)"},
    };
    i.signature =
        "the residual forms a loop against the input and changes sign with the direction of "
        "motion, so loading and unloading branches are missed in opposite directions";
    i.statistic = {"corr(e, stop_r(u))", input_loop_correlation,
                   "the residual correlates with a hysteresis loop driven by the input, the "
                   "stop operator u − play_r(u) with r = {width} of the input's half range "
                   "(r = {value})"};
    // At one frequency a linear lag draws the same ellipse as a
    // rate-independent loop; only the loop's change with frequency tells
    // them apart.
    i.rivals = {{"msd", ExcitationNeed::SeveralFrequencies},
                {"arx", ExcitationNeed::SeveralFrequencies},
                {"second_mode", ExcitationNeed::SeveralFrequencies}};
    return i;
  }

  // c = (A, beta, gamma).
  static EffectSetup setup(std::span<const double> p, double, std::array<double, 3>& c) {
    c = {p[0], p[1], p[2]};
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) return EffectSetup::Invalid;
    return c[0] == 0.0 ? EffectSetup::PassThrough : EffectSetup::Run;
  }

  // The loop at rest: h[-1] = 0, v[-1] = 0.
  template <class V>
  struct State {
    V h{}, v_prev{};
  };

  // One sample: advances the loop with the drive v and returns the signal
  // minus h.
  template <class V>
  static V sample(const std::array<V, 3>& c, NoAux, State<V>& state, V signal, V v) {
    const V A = c[0], beta = c[1], gamma = c[2];
    const V dv = v - state.v_prev;
    state.v_prev = v;
    state.h = bouc_wen_step(state.h, dv, lane_abs(dv), beta, A, gamma);
    return signal - state.h;
  }

  // h, which stays non-finite once it diverges: a block may stop early.
  static constexpr bool kEarlyExit = true;
  template <class V>
  static V health(const std::array<V, 3>&, const State<V>& state) {
    return state.h;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Hysteresis)
