// Variable-step FxNLMS driven by the normalised change of the error level
// (docs/control.md#vss_fxlms). RECONSTRUCTION: seed 000 names the rule
// ("step size adaptation based on normalized error change") but its formula
// was not available; this is our rebuild, and results made with it are
// labelled reconstructed.
//
// An instantaneous ratio like |e(n) - e(n-1)| / |e(n)| cannot work on a tonal
// error: its statistics depend only on f0/fs, not on whether the loop has
// converged. So the change is measured on a smoothed level P (power, or the
// amplitude envelope), M samples apart:
//
//   P(n)   = lambda P(n-1) + (1 - lambda) level(e(n)),   P(-1) = 0
//   rho(n) = |P(n) - P(n-M)| / (P(n-M) + delta_P)  for n >= M, else 0
//   mu(n)  = clip(alpha mu(n-1) + gamma rho(n), mu_min, mu_max),  mu(0) = mu_max
//
// rho is dimensionless, so the constants suit any sensor scale; it is large
// while the error level moves and small once it has settled, even on a noise
// floor or on harmonics the filter cannot cancel.
#include <cmath>
#include <vector>

#include "plugins/controllers/variable_step.hpp"

namespace hystbench {
namespace {

class VssFxlms : public VariableStepFxlms {
 public:
  static ControllerInfo info() {
    auto specs = params(6e-5, "weight of rho(n) in the step recursion; (1 - alpha) mu_max / "
                              "rho_ref with rho_ref = 0.5");
    specs.push_back(ParamSpec::real("lambda", 0.999, 0.0, 1.0,
                                    "memory of the smoothed error level (0.999: 1 s at 1 kHz)"));
    specs.push_back(ParamSpec::integer("window", 500, 1, 1000000,
                                       "M: samples between the two levels compared"));
    specs.push_back(ParamSpec::real("delta_p", 1e-12, 1e-300, 1e6, "regularisation of rho (> 0)"));
    specs.push_back(ParamSpec::choice("level", "power", {"power", "envelope"},
                                      "smooth e(n)^2 (power) or |e(n)| (amplitude envelope)"));
    ControllerInfo info{
        "vss_fxlms",
        "FxNLMS with a step driven by the normalised change of the smoothed error level "
        "(reconstructed)",
        "RECONSTRUCTION of the VSS-FxLMS of seed 000 (Umar et al., J. Low Freq. Noise Vib. "
        "Active Control, 2024, doi:10.1177/14613484241295460), keeping Kwong and Johnston's "
        "recursion (IEEE TSP 40(7), 1992) with a normalised error-change drive; constants are "
        "this project's choice (docs/control.md#vss_fxlms)",
        specs};
    info.reconstructed = true;
    return info;
  }
  explicit VssFxlms(const Params& p)
      : VariableStepFxlms(p),
        lambda_(p.real("lambda")),
        delta_p_(p.real("delta_p")),
        envelope_(p.text("level") == "envelope"),
        levels_(static_cast<std::size_t>(p.integer("window")), 0.0) {}

 protected:
  double next_step(double e) override {
    level_ = lambda_ * level_ + (1.0 - lambda_) * (envelope_ ? std::abs(e) : e * e);
    const std::size_t slot = static_cast<std::size_t>(n_ % levels_.size());
    const double before = levels_[slot];  // P(n - M) once n >= M
    const double rho =
        n_ >= static_cast<long>(levels_.size()) ? std::abs(level_ - before) / (before + delta_p_) : 0.0;
    levels_[slot] = level_;
    return n_++ == 0 ? mu_max() : advance_then_use(rho);
  }
  void reset_drive() override {
    level_ = 0.0;
    n_ = 0;
    std::fill(levels_.begin(), levels_.end(), 0.0);
  }

 private:
  double lambda_, delta_p_;
  bool envelope_;
  std::vector<double> levels_;  // ring of the last M levels
  double level_ = 0.0;
  long n_ = 0;
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_CONTROLLER(hystbench::VssFxlms)
