// Bouc-Wen oscillator: hysteretic restoring force fed back from the output
// velocity inside a mass-spring-damper (Noel & Schoukens 2016 benchmark form):
//
//   m y'' + c y' + k y + z = u,   z' = alpha y' - beta (gamma |y'| z + delta y' |z|),   nu = 1.
//
// Normalised, identifiable form with unit static gain (divide by k; y and z
// in normalised output units, z_n = z / (k y_rms)):
//
//   y''/wn^2 + 2 zeta y'/wn + y + z_n = w
//   z_n' = a y' - bg |y'| z_n - bd y' |z_n|
//
// with wn = 2 pi / period = sqrt(k/m), zeta = c / (2 sqrt(k m)), a = alpha/k,
// bg = beta gamma y_rms, bd = beta delta y_rms. beta alone is not
// identifiable for nu = 1 (only beta gamma and beta delta enter); nu is
// fixed at 1, which makes the loop rate-independent (z_n depends on the path
// of y, not on its speed). At a = 0, z_n stays 0: a linear oscillator.
//
// The natural period (not the frequency) and the damping ratio carry the
// names of msd's parameters, so that adding this effect to a model with msd
// starts from msd's resonance. Period 0 is an infinitely stiff oscillator:
// the effect passes its input through exactly, which makes it neutral
// (period 0, alpha 0) when added to a model without msd.
//
// The oscillator and its integration are shared with duffing
// (oscillator.hpp); this file is the Bouc-Wen law.
#include <cmath>
#include <optional>
#include <span>
#include <string>

#include "framework/core/text.hpp"
#include "framework/model/regressors.hpp"
#include "problems/hammerstein/effects/oscillator.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, ŷ − play_r(ŷ)), the stop operator of the model
// output at the width r (1/16 .. 1/2 of its half range) where it is largest.
// Here the hysteretic force z is driven by the output's motion inside the
// oscillator, not by the input: a linear oscillator fits small strokes
// (z ≈ alpha·y), and the residual is z's departure from that, a loop that
// saturates with the output's stroke. Near the resonance the output's phase
// departs from the input's, so this loop in ŷ differs from the input-driven
// loop of `hysteresis` (which correlates e with the stop operator of u).
// About ±1/√N for a white residual. (Noel & Schoukens 2016; Krasnosel'skii &
// Pokrovskii, Systems with Hysteresis, 1989, stop operator.)
SignatureValue output_loop_correlation(const ResidualView& r) {
  const LoopCorrelation loop = loop_correlation(r.e, r.y_model);
  return {loop.correlation, {{"width", loop.width}}};
}

// β·γ sets the loop: with y' > 0 and z > 0, dz/dy = a − (bg + bd)·z going
// up and a − (bd − bg)·z coming down, so the branches part by 2·bg·z. With
// bg small beside bd, z is one function of y: a nonlinear spring whose
// stiffness dz/dy grows with |z| when bd < 0 (hardening) and falls when
// bd > 0 (softening). A loop narrower than a tenth of that change is not
// told as hysteresis.
constexpr double kLoopShare = 0.1;

std::string loop_reading(std::span<const double> p) {
  const double a = p[2], bg = p[3], bd = p[4];
  if (a == 0.0) return "";
  const std::string values = "β·γ = " + format_number("%.3g", bg) + ", β·δ = " + format_number("%.3g", bd) +
                             " (normalised)";
  if (std::abs(bg) > kLoopShare * std::abs(bd)) return "";
  if (bd == 0.0) return "has no loop and a constant stiffness (" + values + "): a linear spring, not hysteresis";
  return "has no loop (" + values + ", |β·γ| under a tenth of |β·δ|): a " +
         (bd < 0.0 ? "hardening" : "softening") + " spring, not hysteresis";
}

struct BoucWen {
  static EffectInfo info() {
    EffectInfo i;
    i.name = "feedback_hysteresis";
    i.summary =
        "Bouc-Wen oscillator: hysteretic restoring force driven by the output velocity "
        "inside the mass-spring-damper (nu = 1)";
    i.citation = "Noel & Schoukens, Hysteretic benchmark with a dynamic nonlinearity, 2016";
    i.stage = EffectStage::Dynamics;
    i.extends = "msd";
    i.params = oscillator_params({
        {"alpha", 0.0, 4.0, 0.0, 0, 0, "",
         "hysteretic stiffness relative to the linear one, alpha/k (0: no hysteresis)"},
        {"beta_gamma", -3.0, 3.0, 0.0, -1, 0, "",
         "beta*gamma: loop shape term |y'| z (physical value in 1/output unit)"},
        {"beta_delta", -3.0, 3.0, 0.0, -1, 0, "",
         "beta*delta: loop shape term y' |z| (physical value in 1/output unit)"},
    });
    i.signature =
        "a Hammerstein chain fits the low-amplitude part but the error grows with amplitude "
        "near the resonance: the hysteresis is driven by the output velocity inside the "
        "oscillator, not by the input";
    i.statistic = {"corr(e, stop_r(ŷ))", output_loop_correlation,
                   "the residual correlates with a hysteresis loop driven by the model output, "
                   "the stop operator ŷ − play_r(ŷ) with r = {width} of its half range "
                   "(r = {value})"};
    i.reading = loop_reading;
    return i;
  }


  // p = (alpha, beta_gamma, beta_delta); the force is rate-independent, so
  // the coefficients do not depend on the time unit ws.
  static std::optional<OscillatorLaw> coefficients(std::span<const double> p, double) {
    const double a = p[0], bg = p[1], bd = p[2];
    if (!std::isfinite(a) || !std::isfinite(bg) || !std::isfinite(bd) || a <= -1.0) return std::nullopt;
    return OscillatorLaw{{a, bg, bd}, 1.0 + std::max(a, 0.0), a != 0.0};
  }

  // Restoring force y + z.
  template <class V>
  static V excess(const OscillatorRates<V>&, V w, V y, V, V z) {
    return w - y - z;
  }

  // z' = a y' − bg |y'| z − bd y' |z|.
  template <class V>
  static V zdot(const OscillatorRates<V>& c, V, V v, V z) {
    return c.p0 * v - c.p1 * lane_abs(v) * z - c.p2 * v * lane_abs(z);
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Oscillator<hystbench::BoucWen>)
