#pragma once
// A vibration controller in the feedforward loop of docs/control.md: it turns
// the reference x(n) into the control output u(n), and adapts once the error
// e(n) has been read. Controllers are plugins, registered by one macro:
//
//   class MyController : public hystbench::Controller {
//    public:
//     static hystbench::ControllerInfo info();  // name, parameters, citation
//     explicit MyController(const hystbench::Params& params);
//     ...
//   };
//   HYSTBENCH_CONTROLLER(MyController)
//
// The loop (control_loop.hpp) owns the plant, the noise, the
// secondary-path estimate and the logs; a controller never sees them.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/parameters.hpp"
#include "framework/core/registry.hpp"

namespace hystbench {

class Controller {
 public:
  virtual ~Controller() = default;
  // Back to the initial state (zero weights, initial step size).
  virtual void reset() = 0;
  // Control output u(n) once the reference sample x(n) is known.
  virtual double output(double x) = 0;
  // Adaptation after e(n) is read; `filtered` is the reference passed
  // through the secondary-path estimate, x'(n).
  virtual void adapt(double error, double filtered) = 0;
  // For the logs: the step size used by the last adaptation and the norm of
  // the weights (both 0 for a controller without them).
  virtual double step_size() const = 0;
  virtual double weight_norm() const = 0;
};

struct ControllerInfo {
  std::string name;      // registry key, as written in experiment files
  std::string summary;   // one line
  std::string citation;  // reference; say here what is a reconstruction
  std::vector<ParamSpec> params;
  // True when results made with it must be labelled reconstructed.
  bool reconstructed = false;
  // Filled in by HYSTBENCH_CONTROLLER; plugins leave it out.
  std::function<std::unique_ptr<Controller>(const Params&)> create = nullptr;
};

using ControllerRegistry = Registry<ControllerInfo>;

}  // namespace hystbench

#define HYSTBENCH_CONTROLLER(Class) \
  HYSTBENCH_REGISTER_PLUGIN(::hystbench::ControllerInfo, Class, ::hystbench::Params)
