// Constant sensor offset: y + c0.
#include <array>

#include "framework/model/effect.hpp"
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

class Offset : public Effect {
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
  bool apply(std::span<const double> p, const SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    run(std::array<double, 1>{p[0]}, signal.data(), signal.size());
    return true;
  }

  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext&) const override {
    return kernel_stepper<Stateless>(
        [c = std::array<double, 1>{p[0]}](Stateless&, double signal, double) { return sample(c, signal); });
  }

  bool has_lanes() const override { return true; }
  void apply_lanes(const LaneParams& p, const LaneContext&, std::span<LaneVector> signal,
                   LaneMask& ok) const override {
    const auto setup = [](std::span<const double> q, std::array<double, 1>& c) {
      c = {q[0]};
      return EffectSetup::Run;
    };
    run_lanes<1>(p, signal, ok, setup, [&](const std::array<LaneVector, 1>& c) {
      return run(c, signal.data(), Eigen::Index(signal.size()));
    });
  }

 private:
  // One sample, shared by the batch and streaming forms.
  template <class V>
  static V sample(const std::array<V, 1>& c, V signal) {
    return signal + c[0];
  }

  // A non-finite offset is caught by the model's final check, as in apply().
  template <class V>
  static V run(const std::array<V, 1>& c, V* s, Eigen::Index n) {
    for (Eigen::Index k = 0; k < n; ++k) s[k] = sample(c, s[k]);
    return V{};
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Offset)
