// The MFC smart cantilever of seed 000 as a modal model
// (docs/control.md#plant): an Euler-Bernoulli clamped-free beam truncated to
// 2-4 modes, a control and a disturbance patch acting as end-moment pairs
// (modal input L [phi'(x2) - phi'(x1)]), a displacement sensor (phi(x_s)).
// The beam length puts the second mode at `second_mode_hz` (20.61 Hz, the
// disturbance of seed 000). Gains are set at construction so that the
// disturbance alone gives a steady sensor amplitude of 1, and the control
// path has gain 1 per volt at the disturbance frequency.
#include <array>
#include <cmath>

#include "framework/control/high_pass_stream.hpp"
#include "framework/control/modal_stream.hpp"
#include "framework/control/plant.hpp"
#include "framework/core/error.hpp"

namespace hystbench {
namespace {

// Roots of cos(bL) cosh(bL) = -1, the clamped-free frequency equation.
constexpr std::array<double, 4> kBetaL = {1.875104069, 4.694091133, 7.854757438, 10.99554073};

struct ModeShape {
  double k, s;  // wavenumber 1/m, and the clamped-free shape coefficient
  double value(double x) const {
    return std::cosh(k * x) - std::cos(k * x) - s * (std::sinh(k * x) - std::sin(k * x));
  }
  double slope(double x) const {
    return k * (std::sinh(k * x) + std::sin(k * x) - s * (std::cosh(k * x) - std::cos(k * x)));
  }
};

ModeShape shape(int i, double length) {
  const double bl = kBetaL[i];
  return {bl / length, (std::cosh(bl) + std::cos(bl)) / (std::sinh(bl) + std::sin(bl))};
}

class MfcBeam : public Plant {
 public:
  static PlantInfo info() {
    return {"mfc_beam",
            "Cantilever with a control and a disturbance MFC patch and a displacement sensor, "
            "modal model with exact zero-order-hold sampling",
            "Euler-Bernoulli modal model (e.g. L. Meirovitch, Fundamentals of Vibrations, 2001); "
            "patch as an end-moment pair. RESOLUTION: geometry, damping and gain normalisation "
            "are this project's choices, made to put the second mode at the disturbance of "
            "seed 000 (docs/control.md#plant)",
            {ParamSpec::integer("modes", 3, 2, 4, "modes kept"),
             ParamSpec::real("damping", 0.01, 1e-6, 0.99, "damping ratio of every mode"),
             ParamSpec::real("second_mode_hz", 20.61, 0.01, 1e5,
                             "natural frequency of mode 2; sets the beam length"),
             ParamSpec::real("thickness_m", 1e-3, 1e-6, 1.0, "beam thickness"),
             ParamSpec::real("youngs_modulus_pa", 68.9e9, 1.0, 1e13, "E (aluminium)"),
             ParamSpec::real("density_kg_m3", 2700.0, 1.0, 1e5, "rho (aluminium)"),
             ParamSpec::real("control_from_m", 0.010, 0.0, 100.0, "control patch start"),
             ParamSpec::real("control_to_m", 0.095, 0.0, 100.0, "control patch end"),
             ParamSpec::real("disturbance_from_m", 0.150, 0.0, 100.0, "disturbance patch start"),
             ParamSpec::real("disturbance_to_m", 0.235, 0.0, 100.0, "disturbance patch end"),
             ParamSpec::real("sensor_at", 0.9, 0.0, 1.0, "sensor position, fraction of the length"),
             ParamSpec::integer("extra_delay_samples", 0, 0, 10000,
                                "pure delay on the control path (amplifier, converters)"),
             ParamSpec::real("sensor_highpass_hz", 0.0, 0.0, 1e5,
                             "corner of a first-order high-pass on the sensor (AC coupling; 0: "
                             "none), which removes static deflection")}};
  }

  MfcBeam(const Params& p, const PlantSetup& setup) : setup_(setup) {
    const double h = p.real("thickness_m");
    const double c = h * std::sqrt(p.real("youngs_modulus_pa") / (12.0 * p.real("density_kg_m3")));
    // w_i = (beta_i L)^2 c / L^2, solved for L at mode 2.
    length_ = kBetaL[1] * std::sqrt(c / (2.0 * M_PI * p.real("second_mode_hz")));
    check_patch(p, "control", length_);
    check_patch(p, "disturbance", length_);
    delay_ = p.integer("extra_delay_samples");
    highpass_hz_ = p.real("sensor_highpass_hz");
    const double sensor = p.real("sensor_at") * length_;
    for (int i = 0; i < p.integer("modes"); ++i) {
      const ModeShape s = shape(i, length_);
      const double omega = kBetaL[i] * kBetaL[i] * c / (length_ * length_);
      auto patch = [&](const char* which) {
        const std::string key = which;
        return length_ * (s.slope(p.real(key + "_to_m")) - s.slope(p.real(key + "_from_m")));
      };
      control_.push_back({omega, p.real("damping"), patch("control"), s.value(sensor)});
      disturbance_.push_back({omega, p.real("damping"), patch("disturbance"), s.value(sensor)});
    }
    // Normalisation at the disturbance frequency (sensor units).
    control_gain_ = 1.0 / std::abs(control_response(setup.disturbance_hz));
    disturbance_gain_ =
        1.0 / (setup.disturbance_amplitude * std::abs(disturbance_response(setup.disturbance_hz)));
    if (!std::isfinite(control_gain_) || !std::isfinite(disturbance_gain_))
      throw InputError("plant.params: the sensor (sensor_at) or a patch sits where the beam does not "
                       "respond at " + std::to_string(setup.disturbance_hz) +
                       " Hz; move it (e.g. sensor_at 0.9)");
    for (Mode& m : control_) m.input *= control_gain_;
    for (Mode& m : disturbance_) m.input *= disturbance_gain_;
  }

  std::unique_ptr<SignalStream> control_path() const override {
    return sensed(std::make_unique<ModalStream>(control_, 1.0 / setup_.sample_rate_hz, delay_));
  }
  std::unique_ptr<SignalStream> disturbance_path() const override {
    return sensed(std::make_unique<ModalStream>(disturbance_, 1.0 / setup_.sample_rate_hz));
  }
  std::complex<double> control_response(double hz) const override {
    return modal_response(control_, hz) * HighPassStream::response(highpass_hz_, hz);
  }
  std::complex<double> disturbance_response(double hz) const override {
    return modal_response(disturbance_, hz) * HighPassStream::response(highpass_hz_, hz);
  }
  nlohmann::json details() const override {
    nlohmann::json modes = nlohmann::json::array();
    for (std::size_t i = 0; i < control_.size(); ++i)
      modes.push_back({{"frequency_hz", control_[i].omega / (2.0 * M_PI)},
                       {"control_input", control_[i].input / control_gain_},
                       {"disturbance_input", disturbance_[i].input / disturbance_gain_},
                       {"sensor", control_[i].output}});
    return {{"length_m", length_},
            {"control_gain", control_gain_},
            {"disturbance_gain", disturbance_gain_},
            {"modes", modes}};
  }

 private:
  // The beam's output as the sensor reports it.
  std::unique_ptr<SignalStream> sensed(std::unique_ptr<SignalStream> beam) const {
    if (highpass_hz_ <= 0.0) return beam;
    return std::make_unique<HighPassStream>(std::move(beam), highpass_hz_, 1.0 / setup_.sample_rate_hz);
  }

  static void check_patch(const Params& p, const std::string& which, double length) {
    const double from = p.real(which + "_from_m"), to = p.real(which + "_to_m");
    if (!(from < to) || to > length)
      throw InputError("plant.params." + which + "_from_m/" + which + "_to_m: the patch [" +
                       std::to_string(from) + ", " + std::to_string(to) +
                       "] m must be an interval on the beam, whose length is " +
                       std::to_string(length) + " m");
  }

  PlantSetup setup_;
  double length_ = 0.0;
  int delay_ = 0;
  double highpass_hz_ = 0.0;
  std::vector<Mode> control_, disturbance_;
  double control_gain_ = 1.0, disturbance_gain_ = 1.0;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_PLANT(hystbench::MfcBeam)
