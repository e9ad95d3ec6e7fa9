// Linear sensor drift in time (output stage).
//
//   signal[k] += c1 · t[k]
//
// t in seconds from the first sample (SignalContext::time). Neutral c1 = 0.
// Units: y/s.
#include <array>
#include <cmath>

#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, t). A missing drift c1·t leaves a linear trend
// in the residual; Pearson's r with time measures how much of the residual it
// is, and is about ±1/√N for a white residual.
// (Ljung, System Identification, 2nd ed., 1999, §16.6: residual analysis.)
SignatureValue time_correlation(const ResidualView& r) { return {correlation(r.e, r.t)}; }

class Drift : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "drift";
    i.summary = "linear sensor drift c1·t added to the output";
    i.citation = "docs/discovery.md (sensor offset and drift y + c0 + c1·t)";
    i.stage = EffectStage::Output;
    i.params = {{"c1", -1.0, 1.0, 0.0, 1, 0, "1/s", "drift rate"}};
    i.signature = "the residual has a linear trend in time that does not depend on the input";
    i.statistic = {"corr(e, t)", time_correlation,
                   "the residual correlates with time (r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    std::array<double, 1> c;
    const EffectSetup s = gain_like_setup(p, c);
    if (s != EffectSetup::Run) return s == EffectSetup::PassThrough;
    if (!ctx.time || ctx.time->size() != signal.size()) return false;
    run(c, ctx.time->data(), signal.data(), signal.size());
    return true;
  }

  bool has_lanes() const override { return true; }
  void apply_lanes(const LaneParams& p, const LaneContext& ctx, std::span<LaneVector> signal,
                   LaneMask& ok) const override {
    if (!ctx.time || std::size_t(ctx.time->size()) != signal.size()) return ok.fill(false);
    run_lanes<1>(p, signal, ok, gain_like_setup, [&](const std::array<LaneVector, 1>& c) {
      return run(c, ctx.time->data(), signal.data(), Eigen::Index(signal.size()));
    });
  }

  // Time is k·Ts at sample k, counted by the stepper; the record's time
  // column (from 0) equals it to rounding.
  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext& ctx) const override {
    std::array<double, 1> c;
    return stepper_for(gain_like_setup(p, c), [&] {
      struct Clock {
        double samples = 0.0;
      };
      return kernel_stepper<Clock>([c, ts = ctx.sample_time](Clock& clock, double signal, double) {
        return sample(c, signal, ts * clock.samples++);
      });
    });
  }

 private:
  // One sample, shared by the batch and streaming forms: signal + c1·t.
  template <class V>
  static V sample(const std::array<V, 1>& c, V signal, double t) {
    return signal + c[0] * t;
  }

  // Returns c1.
  template <class V>
  static V run(const std::array<V, 1>& c, const double* t, V* s, Eigen::Index n) {
    for (Eigen::Index k = 0; k < n; ++k) s[k] = sample(c, s[k], t[k]);
    return c[0];
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Drift)
