#include "framework/control/uncontrolled.hpp"

namespace hystbench {
namespace {

// No estimate is needed when nothing adapts.
class ZeroStream final : public SignalStream {
 public:
  void reset() override {}
  double step(double) override { return 0.0; }
  std::unique_ptr<SignalStream> clone() const override { return std::make_unique<ZeroStream>(); }
};

}  // namespace

LoopTrace run_uncontrolled(const LoopPaths& paths, LoopSettings settings, std::uint64_t noise_seed) {
  settings.divergence_level = 0.0;
  settings.uncontrolled_level = 0.0;
  Uncontrolled none;
  return run_loop(paths, ZeroStream(), none, settings, noise_seed);
}

}  // namespace hystbench
