// Constant sensor offset: y + c0.
#include <array>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: mean(e) / std(e), the residual mean in residual
// standard deviations. A missing offset c0 shifts the whole residual by c0,
// whatever the input; a white zero-mean residual gives about ±1/√N.
// (Ljung, System Identification, 2nd ed., 1999, §16.6: residual analysis.)
SignatureValue mean_over_std(const ResidualView& r) {
  if (r.e.size() < 2) return {};
  return {r.e.mean() / standard_deviation(r.e)};
}

class Offset : public KernelEffect<Offset, 1, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "offset";
    i.summary = "constant sensor offset added to the output";
    i.stage = EffectStage::Output;
    i.params = {{"c0", -5.0, 5.0, 0.0, 1, 0, "", "offset"}};
    i.citation = "docs/discovery.md (sensor offset and drift y + c0 + c1·t)";
    i.signature = "the residual has a non-zero mean that does not depend on the input";
    i.statistic = {"mean(e)/std(e)", mean_over_std,
                   "the residual mean is {value} residual standard deviations"};
    return i;
  }

  // c = (c0); every value runs, a non-finite one is caught by the model's
  // final check.
  static EffectSetup setup(std::span<const double> p, double, std::array<double, 1>& c) {
    c = {p[0]};
    return EffectSetup::Run;
  }

  // One sample: signal + c0.
  template <class V>
  static V sample(const std::array<V, 1>& c, NoAux, State<V>&, V signal, double) {
    return signal + c[0];
  }

  template <class V>
  static V health(const std::array<V, 1>&, const State<V>&) {
    return V{};
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Offset)
