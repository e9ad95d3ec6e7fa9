// Asymmetric static term d2·v² (nonlinearity stage).
//
//   signal[k] += d2·v[k]²
//
// v is the stage input (normalised drive after the input effects); with the
// model's gain·v this is the seed's d1·u + d2·u² (docs/design.md#hammerstein-seed-model;
// Fu et al.,
// asymmetric Bouc-Wen for MFC). Neutral d2 = 0. Units: y/u².
#include <array>
#include <cmath>

#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, u² − mean u²), the u²′ correlation test of
// Billings & Voon (Int. J. Control 44, 1986) for a missing even nonlinearity:
// d2·v² is what a model without it leaves behind, and Pearson's r removes the
// mean. About ±1/√N for a residual independent of the input.
SignatureValue square_correlation(const ResidualView& r) {
  return {correlation(r.e, r.u.cwiseAbs2())};
}

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
    i.statistic = {"corr(e, u² − mean u²)", square_correlation,
                   "the residual correlates with u² − mean(u²) (r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    std::array<double, 1> c;
    const EffectSetup s = gain_like_setup(p, c);
    if (s != EffectSetup::Run) return s == EffectSetup::PassThrough;
    if (!ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    return std::isfinite(run(c, ctx.stage_input->data(), signal.data(), signal.size()));
  }

  bool has_lanes() const override { return true; }
  void apply_lanes(const LaneParams& p, const LaneContext& ctx, std::span<LaneVector> signal,
                   LaneMask& ok) const override {
    if (ctx.stage_input.size() != signal.size()) return ok.fill(false);
    run_lanes<1>(p, signal, ok, gain_like_setup, [&](const std::array<LaneVector, 1>& c) {
      return run(c, ctx.stage_input.data(), signal.data(), Eigen::Index(signal.size()));
    });
  }

  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext&) const override {
    std::array<double, 1> c;
    return stepper_for(gain_like_setup(p, c), [&] {
      return kernel_stepper<Stateless>(
          [c](Stateless&, double signal, double v) { return sample(c, signal, v); });
    });
  }

 private:
  // One sample, shared by the batch and streaming forms: signal + d2·v².
  template <class V>
  static V sample(const std::array<V, 1>& c, V signal, V v) {
    return signal + c[0] * (v * v);
  }

  // Returns d2 (finite: nothing here can diverge).
  template <class V>
  static V run(const std::array<V, 1>& c, const V* v, V* s, Eigen::Index n) {
    for (Eigen::Index k = 0; k < n; ++k) s[k] = sample(c, s[k], v[k]);
    return c[0];
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Asymmetry)
