#include "framework/control/secondary_path.hpp"

#include "framework/core/eigen.hpp"
#include <cmath>

#include "framework/control/actuator_model.hpp"
#include "framework/control/first_harmonic.hpp"
#include "framework/control/scaled_stream.hpp"
#include "framework/control/tapped_delay_line.hpp"
#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {
namespace {

// A finite impulse response as a stream: y(n) = sum_k h_k u(n - k).
class FirStream final : public SignalStream {
 public:
  explicit FirStream(Eigen::VectorXd h) : h_(std::move(h)), past_(int(h_.size())) {}
  void reset() override { past_.reset(int(h_.size())); }
  double step(double u) override {
    past_.push(u);
    return h_.dot(past_.recent());
  }
  std::unique_ptr<SignalStream> clone() const override {
    return std::make_unique<FirStream>(*this);
  }

 private:
  Eigen::VectorXd h_;
  TappedDelayLine past_;
};

// Normalised LMS on white noise through the true path (Kuo & Morgan's
// offline secondary-path modelling), with the loop's sensor noise.
SecondaryPath fir_lms(const nlohmann::json& spec, const EstimateContext& c, const std::string& where) {
  const Params p = validate_params(
      {ParamSpec::integer("taps", 512, 1, 100000, "FIR length"),
       ParamSpec::real("seconds", 60.0, 0.01, 1e5, "length of the identification run"),
       ParamSpec::real("excitation", 1.0, 1e-12, 1e12, "standard deviation of the white noise"),
       ParamSpec::real("step", 0.1, 1e-9, 2.0, "normalised LMS step")},
      spec, where);
  const int taps = p.integer("taps");
  Eigen::VectorXd h = Eigen::VectorXd::Zero(taps);
  TappedDelayLine past(taps);
  auto path = c.true_path.clone();
  path->reset();
  Rng rng(c.identification_seed);
  const long n = std::lround(p.real("seconds") * c.loop.sample_rate_hz);
  for (long k = 0; k < n; ++k) {
    const double u = p.real("excitation") * rng.normal();
    past.push(u);
    const auto x = past.recent();
    const double y = path->step(u) + c.loop.noise_sd * rng.normal();
    const double err = y - h.dot(x);
    h += (p.real("step") * err / (1e-12 + x.squaredNorm())) * x;
  }
  return {std::make_unique<FirStream>(h),
          "FIR, " + std::to_string(taps) + " taps, identified by NLMS from white noise", {}};
}

SecondaryPath identified_model(const nlohmann::json& spec, const EstimateContext& c,
                               const std::string& where) {
  nlohmann::json model = spec;
  const bool then_plant = optional_flag(spec, "then_plant", false, where);
  model.erase("then_plant");
  ActuatorModel a = actuator_model(model, c.loop, c.base_dir, where);
  if (!then_plant) return {std::move(a.stream), "identified model " + a.description, {}};
  return {std::make_unique<SeriesStream>(std::move(a.stream), c.plant.control_path()),
          "identified actuator " + a.description + ", then the plant's linear control path", {}};
}

SecondaryPath build(const nlohmann::json& spec, const EstimateContext& c, const std::string& where) {
  if (!spec.is_object() || !spec.contains("type") || !spec["type"].is_string())
    throw InputError(where + ".type: give \"linear_true\", \"model\" or \"fir_lms\"");
  const std::string type = spec["type"].get<std::string>();
  nlohmann::json rest = spec;
  rest.erase("type");
  if (type == "linear_true") {
    require_known_keys(rest, {}, where);
    return {c.plant.control_path(), "the plant's exact linear control path", {}};
  }
  if (type == "model") {
    auto keys = actuator_model_keys();
    keys.push_back("then_plant");
    require_known_keys(rest, keys, where);
    return identified_model(rest, c, where);
  }
  if (type == "fir_lms") return fir_lms(rest, c, where);
  throw InputError(where + ".type: unknown '" + type +
                   "'; give \"linear_true\", \"model\" or \"fir_lms\"");
}

}  // namespace

SecondaryPath secondary_path(const nlohmann::json& spec, const EstimateContext& c,
                             const std::string& where) {
  SecondaryPath s = build(spec, c, where);
  const HarmonicProbe probe = probe_at(c.loop, c.loop.reference_amplitude);
  auto truth = c.true_path.clone();
  const auto ratio = first_harmonic(*s.stream, probe) / first_harmonic(*truth, probe);
  s.error = {std::arg(ratio) * 180.0 / M_PI, std::abs(ratio)};
  return s;
}

}  // namespace hystbench
