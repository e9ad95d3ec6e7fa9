// Asymmetric static term d2·v² (nonlinearity stage).
//
//   signal[k] += d2·v[k]²
//
// v is the stage input (normalised drive after the input effects); with the
// model's gain·v this is the seed's d1·u + d2·u² (DESIGN.md §3; Fu et al.,
// asymmetric Bouc-Wen for MFC). Neutral d2 = 0. Units: y/u².
#include <cmath>

#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Asymmetry : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "asymmetry";
    i.summary = "quadratic static term d2·v²: loops not symmetric about their centre";
    i.citation =
        "Fu et al., Sens. Actuators A, 2022 (asymmetric Bouc-Wen model of an MFC); "
        "Billings & Voon, Int. J. Control 44 (1986) (u² correlation test)";
    i.stage = EffectStage::Nonlinearity;
    i.params = {{"d2", -5.0, 5.0, 0.0, 1, -2, "", "quadratic coefficient of the static part"}};
    i.signature =
        "the residual correlates with u² minus its mean, shows a second harmonic under a pure "
        "sine and the loop centre is shifted";
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double d2 = p[0];
    if (!std::isfinite(d2)) return false;
    if (d2 == 0.0) return true;
    if (!ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    signal.array() += d2 * ctx.stage_input->array().square();
    return true;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Asymmetry)
