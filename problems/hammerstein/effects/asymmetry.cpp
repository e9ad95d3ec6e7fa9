// Asymmetric static term d2·v² (nonlinearity stage).
//
//   signal[k] += d2·v[k]²
//
// v is the stage input (normalised drive after the input effects); with the
// model's gain·v this is the seed's d1·u + d2·u² (docs/models.md#hammerstein-seed-model;
// Fu et al.,
// asymmetric Bouc-Wen for MFC). Neutral d2 = 0. Units: y/u².
#include <array>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
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

class Asymmetry : public KernelEffect<Asymmetry, 1, EffectDrive::StageInput> {
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

  // c = (d2).
  static EffectSetup setup(std::span<const double> p, double, std::array<double, 1>& c) {
    return gain_like_setup(p, c);
  }

  // One sample: signal + d2·v².
  template <class V>
  static V sample(const std::array<V, 1>& c, NoAux, State<V>&, V signal, V v) {
    return signal + c[0] * (v * v);
  }

  // d2 (finite: nothing here can diverge).
  template <class V>
  static V health(const std::array<V, 1>& c, const State<V>&) {
    return c[0];
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Asymmetry)
