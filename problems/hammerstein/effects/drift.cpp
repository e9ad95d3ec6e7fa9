// Linear sensor drift in time (output stage).
//
//   signal[k] += c1 · t[k]
//
// t in seconds from the first sample (SignalContext::time). Neutral c1 = 0.
// Units: y/s.
#include <array>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, t). A missing drift c1·t leaves a linear trend
// in the residual; Pearson's r with time measures how much of the residual it
// is, and is about ±1/√N for a white residual.
// (Ljung, System Identification, 2nd ed., 1999, §16.6: residual analysis.)
SignatureValue time_correlation(const ResidualView& r) { return {correlation(r.e, r.t)}; }

class Drift : public KernelEffect<Drift, 1, EffectDrive::Time> {
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

  // c = (c1).
  static EffectSetup setup(std::span<const double> p, double, std::array<double, 1>& c) {
    return gain_like_setup(p, c);
  }

  // One sample: signal + c1·t.
  template <class V>
  static V sample(const std::array<V, 1>& c, NoAux, State<V>&, V signal, double t) {
    return signal + c[0] * t;
  }

  // c1.
  template <class V>
  static V health(const std::array<V, 1>& c, const State<V>&) {
    return c[0];
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Drift)
