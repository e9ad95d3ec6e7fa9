// Constant sensor offset: y + c0.
#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Offset : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "offset";
    i.summary = "constant sensor offset added to the output";
    i.stage = EffectStage::Output;
    i.params = {{"c0", -5.0, 5.0, 0.0, 1, 0, "", "offset"}};
    i.citation = "DISCOVERY.md §2 (sensor offset and drift y + c0 + c1·t)";
    i.signature = "the residual has a non-zero mean that does not depend on the input";
    return i;
  }
  bool apply(std::span<const double> p, const SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    signal.array() += p[0];
    return true;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Offset)
