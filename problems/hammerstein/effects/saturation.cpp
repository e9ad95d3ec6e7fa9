// Smooth saturation of the static part (nonlinearity stage).
//
//   signal[k] = L·tanh(signal[k] / L),   lambda = 1/L²
//
// It limits the nonlinearity stage's signal as it stands when the effect
// runs: gain·v plus the nonlinearity effects listed before it (list it last
// in that stage to saturate the whole static part). Parameterised by the
// inverse squared limit lambda = 1/L² ≥ 0 so that lambda = 0 (L → ∞) is an
// exact pass-through inside the box, and so that the output moves linearly
// away from it: L·tanh(s/L) = s − lambda·s³/3 + O(lambda²). With 1/L as the
// parameter the first derivative at the neutral value would be zero, and a
// local search or a score test started there would not see the effect.
// Units: lambda in 1/y².
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: (share of the SSE in the top |u − mean u| bin) /
// (share of the samples in it). A missing limit bends the response only at the
// largest drive, so the error crowds into the top amplitude bin; a residual
// independent of the amplitude gives 1. (Hassani et al. 2014, saturation of
// piezo actuators; bins as in the breakdown tables of `compare`.)
SignatureValue top_bin_error_share(const ResidualView& r) {
  std::vector<double> edges;
  const auto bin = amplitude_bins(r.u, edges);
  double top_sse = 0;
  long top_n = 0;
  for (std::size_t k = 0; k < bin.size(); ++k)
    if (bin[k] == kAmplitudeBins - 1) top_sse += std::pow(r.e[Eigen::Index(k)], 2), ++top_n;
  const double total = r.e.squaredNorm();
  if (bin.empty() || !(edges.back() > 0) || !(total > 0)) return {};
  const double sse_share = top_sse / total, sample_share = double(top_n) / double(bin.size());
  return {sse_share / sample_share, {{"sse_share", sse_share}, {"sample_share", sample_share}}};
}

class Saturation : public KernelEffect<Saturation, 2, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "saturation";
    i.summary = "smooth limit L·tanh(s/L) on the static part's output, parameterised by 1/L²";
    i.citation =
        "Hassani, Tjahjowidodo & Do, Mech. Syst. Signal Process. 49 (2014) (survey); "
        "MATLAB nlhw saturation block";
    i.stage = EffectStage::Nonlinearity;
    i.params = {{"lambda", 0.0, 4.0, 0.0, -2, 0, "",
                 "inverse squared output limit 1/L² (0 = no saturation)"}};
    i.signature =
        "the error is concentrated in the top amplitude bin and the residual carries a third "
        "harmonic of the drive";
    i.statistic = {"top-bin SSE share / sample share", top_bin_error_share,
                   "the top amplitude bin holds {value} times its share of the samples in "
                   "squared error ({sse_share} of the SSE on {sample_share} of the samples)"};
    // At one amplitude a flattened top and an even-order bend are both one
    // fixed distortion of the loop; only a second amplitude shows which
    // grows how.
    i.rivals = {{"asymmetry", ExcitationNeed::SeveralAmplitudes}};
    return i;
  }

  // c = (1/L, L).
  static EffectSetup setup(std::span<const double> p, double /*Ts*/, std::array<double, 2>& c) {
    const double lambda = p[0];
    if (!std::isfinite(lambda) || lambda < 0.0) return EffectSetup::Invalid;
    if (lambda == 0.0) return EffectSetup::PassThrough;
    c = {std::sqrt(lambda), 0.0};
    c[1] = 1.0 / c[0];
    return std::isfinite(c[1]) ? EffectSetup::Run : EffectSetup::Invalid;
  }

  template <class V>
  static V sample(const std::array<V, 2>& c, NoAux, State<V>&, V signal, double) {
    return c[1] * lane_tanh(c[0] * signal);
  }

  // Stateless: nothing can diverge.
  template <class V>
  static V health(const std::array<V, 2>&, const State<V>&) {
    return V{};
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Saturation)
