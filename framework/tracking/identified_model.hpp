#pragma once
// An identified actuator model as the tracking work uses it
// (docs/tracking.md#identified-models): a front, the static and hysteretic
// part an inverse cancels, and a back, the linear part a controller is
// designed on, each run one sample at a time in physical units.
//
//   {"fit": "fit.json"} or {"model": .., "parameters": ..}   a catalog chain: front = input
//                                                            stage, gain and nonlinearity;
//                                                            back = dynamics and output stages
//   {"svr": "svr_model.json"}                                the SVR Hammerstein-like model:
//                                                            front = stage 1, back = stage 2
//
// front(u) is what the input u given now makes enter the back: back(front(u))
// is the output the loop measures one sample after applying u.
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace hystbench {

class IdentifiedModel {
 public:
  virtual ~IdentifiedModel() = default;
  virtual void reset() = 0;
  // The front's output for input u now, in output units; the state stays.
  virtual double trial_front(double u) = 0;
  // The same, and the front moves on.
  virtual double step_front(double u) = 0;
  virtual double step_back(double w) = 0;
  virtual std::unique_ptr<IdentifiedModel> clone() const = 0;
};

struct IdentifiedSource {
  std::string description;
  // The sampling time the model's lags count in (an SVR model's); 0 when
  // the model runs at any rate (a catalog chain is continuous in time).
  double sample_time = 0.0;
  // Throws InputError when the model cannot run at `sample_time`.
  std::function<std::unique_ptr<IdentifiedModel>(double sample_time)> make;
};

// Throws InputError naming `where` and the bad key.
IdentifiedSource read_identified(const nlohmann::json& spec, const std::filesystem::path& base_dir,
                                 const std::string& where);

}  // namespace hystbench
