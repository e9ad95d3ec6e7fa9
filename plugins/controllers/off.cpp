// The uncontrolled baseline as a controller a user can list: u = 0. Every
// experiment also runs it on its own, with the same noise, as the reference
// of the suppression efficiency (docs/control.md#metrics).
#include "framework/control/uncontrolled.hpp"

namespace hystbench {
namespace {

class Off : public Uncontrolled {
 public:
  static ControllerInfo info() {
    return {"off", "No control: u = 0 (the uncontrolled baseline)", "", {}};
  }
  explicit Off(const Params&) {}
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::Off)
