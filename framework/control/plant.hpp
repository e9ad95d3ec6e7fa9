#pragma once
// A vibrating structure for the control loop (docs/control.md#plant): two
// linear paths to one sensor, from the control actuator and from the
// disturbance actuator, sampled at the loop's rate. Any actuator nonlinearity
// of the control path is not the plant's: the loop puts a hystbench model in
// front of control_path() (control_setup.hpp). Plants are plugins:
//
//   class MyPlant : public hystbench::Plant { ... };   // static PlantInfo info();
//   HYSTBENCH_PLANT(MyPlant)                           // MyPlant(const Params&, const PlantSetup&)
#include <complex>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/parameters.hpp"
#include "framework/core/registry.hpp"
#include "framework/model/signal_stream.hpp"

namespace hystbench {

// What a plant is built for: gains are normalised at the disturbance.
struct PlantSetup {
  double sample_rate_hz = 1000.0;
  double disturbance_hz = 20.61;
  double disturbance_amplitude = 3.0;  // V into the disturbance actuator
};

class Plant {
 public:
  virtual ~Plant() = default;
  // Sampled paths, at rest: sensor output at sample n from the inputs up to
  // n - 1 (a sampled loop's one-sample delay).
  virtual std::unique_ptr<SignalStream> control_path() const = 0;
  virtual std::unique_ptr<SignalStream> disturbance_path() const = 0;
  // Continuous-time frequency responses of the same paths, in closed form.
  virtual std::complex<double> control_response(double hz) const = 0;
  virtual std::complex<double> disturbance_response(double hz) const = 0;
  // Derived quantities worth reporting (e.g. natural frequencies, gains).
  virtual nlohmann::json details() const = 0;
};

struct PlantInfo {
  std::string name;
  std::string summary;
  std::string citation;
  std::vector<ParamSpec> params;
  std::function<std::unique_ptr<Plant>(const Params&, const PlantSetup&)> create = nullptr;
};

using PlantRegistry = Registry<PlantInfo>;

}  // namespace hystbench

#define HYSTBENCH_PLANT(Class) \
  HYSTBENCH_REGISTER_PLUGIN(::hystbench::PlantInfo, Class, ::hystbench::Params, ::hystbench::PlantSetup)
