// Linear sensor drift in time (output stage).
//
//   signal[k] += c1 · t[k]
//
// t in seconds from the first sample (SignalContext::time). Neutral c1 = 0.
// Units: y/s.
#include <cmath>

#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Drift : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "drift";
    i.summary = "linear sensor drift c1·t added to the output";
    i.citation = "DISCOVERY.md §2 (sensor offset and drift y + c0 + c1·t)";
    i.stage = EffectStage::Output;
    i.params = {{"c1", -1.0, 1.0, 0.0, 1, 0, "1/s", "drift rate"}};
    i.signature = "the residual has a linear trend in time that does not depend on the input";
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double c1 = p[0];
    if (!std::isfinite(c1)) return false;
    if (c1 == 0.0) return true;
    if (!ctx.time || ctx.time->size() != signal.size()) return false;
    signal += c1 * *ctx.time;
    return true;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Drift)
