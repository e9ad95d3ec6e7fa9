// Rate-independent Bouc-Wen hysteresis (nonlinearity stage).
//
//   h[k] = h[k-1] + A·Δv[k] − β·|Δv[k]|·h[k-1] − γ·Δv[k]·|h[k-1]|,   Δv[k] = v[k] − v[k-1]
//   signal[k] −= h[k]
//
// v is the stage input (the normalised drive after the input effects), so
// the loop is driven by the drive, as h is by u in the seed model's
// h1 = d1·u + d2·u² − h (DESIGN.md §3). A stands for the seed's α·L: the two
// enter only as a product, so one parameter keeps the direction identifiable.
// The loop's branch slopes are set by A, its width saturates at about
// A/(β+γ); none of them can be traded against the model's gain.
//
// Initial state: at rest, v[-1] = 0 and h[-1] = 0, as in the seed model.
// Neutral: A = 0 keeps h ≡ 0 whatever β and γ are.
// Units: A in y/u; β and γ in 1/u (β·|Δv| and γ·Δv are pure numbers).
// A diverging loop (large β·|Δv| with a violent drive) makes apply false.
#include <cmath>

#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Hysteresis : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "hysteresis";
    i.summary = "rate-independent Bouc-Wen hysteresis loop driven by the input increments";
    i.citation =
        "Bouc, Proc. 4th Conf. Nonlinear Oscillations, 1967; Wen, J. Eng. Mech. 102 (1976); "
        "increment form as in the seed Hammerstein model (DESIGN.md §3)";
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
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double A = p[0], beta = p[1], gamma = p[2];
    if (!std::isfinite(A) || !std::isfinite(beta) || !std::isfinite(gamma)) return false;
    if (A == 0.0) return true;
    if (!ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    const double* v = ctx.stage_input->data();
    double* s = signal.data();
    const Eigen::Index n = signal.size();
    double h = 0.0, v_prev = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double dv = v[k] - v_prev;
      v_prev = v[k];
      h = (h * (1.0 - beta * std::abs(dv)) + A * dv) - gamma * dv * std::abs(h);
      s[k] -= h;
      // Once non-finite, h stays non-finite; checking now and then ends a
      // diverging run early without a test on every sample.
      if ((k & 1023) == 1023 && !std::isfinite(h)) return false;
    }
    return std::isfinite(h);
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Hysteresis)
