// Duffing oscillator: a mass-spring-damper whose spring stiffens or softens
// with deflection, and may do so differently in the two directions, with a
// drag that grows with the square of the speed:
//
//   m y'' + c y' + c2 y'|y'| + k (y + k2 y^2 + k3 y^3) = u.
//
// Normalised like feedback_hysteresis (divide by k; y in normalised output
// units, the fitted output having RMS 1):
//
//   y''/wn^2 + 2 zeta y'/wn + drag (y'/wn)|y'/wn| + y + k2 y^2 + k3 y^3 = w,
//
// with k2, k3 and drag relative to the linear stiffness (physical values
// k2 / y_rms, k3 / y_rms^2 and drag / y_rms). k3 > 0 hardens, k3 < 0
// softens (and lets a large stroke escape over the potential's barrier: the
// parameters then fail); k2 makes the spring asymmetric. At k2 = k3 = drag
// = 0 it is msd's linear resonance, integrated in continuous time rather
// than bilinearly.
//
// Why the drag: on Silverbox, once the spring is right, `propose` names
// y'|y'| first, and with it the arrow test's error falls from 0.389 to
// 0.316 mV (docs/discovery.md, "Measured benchmarks"). A quadratic drag is the usual
// amplitude-dependent loss of a vibrating structure (air, fluid, joints):
// its equivalent viscous damping grows in proportion to the amplitude.
//
// Why a catalog effect when feedback_hysteresis can also draw a hardening
// spring (β·γ = 0, β·δ < 0): that spring's force grows exponentially with
// the stroke, z = (a / |β·δ|)(exp(|β·δ| |y|) − 1), so it fits the amplitudes
// it was fitted on and overshoots beyond them. A polynomial spring is what
// an electronic or mechanical Duffing oscillator has; on Silverbox
// (docs/discovery.md, "Measured benchmarks") it extrapolates to the arrow
// test's larger amplitudes where the exponential does not.
//
// The oscillator and its integration are shared with feedback_hysteresis
// (oscillator.hpp); this file is the polynomial law. The law has no internal
// state (z stays 0) and no kinks: y'|y'| is continuously differentiable, so
// RK4 keeps its order through a velocity reversal to within a term that the
// small drag makes negligible.
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>

#include "framework/core/text.hpp"
#include "framework/model/regressors.hpp"
#include "problems/hammerstein/effects/oscillator.hpp"

namespace hystbench {
namespace {

// The reading quotes the stiffness at this many output RMS from rest: a
// record's peaks sit at 1.4 (a sine) to about 3 RMS (Gaussian noise).
constexpr double kReadingStroke = 2.0;

// Signature statistic: the partial correlation of e with ŷ² and ŷ³ given ŷ,
// sqrt((R²(e; ŷ, ŷ², ŷ³) − R²(e; ŷ)) / (1 − R²(e; ŷ))): what the powers
// explain of the residual that ŷ (a gain error) leaves. A missing
// polynomial spring leaves −(k2 ŷ² + k3 ŷ³) through the dynamics in the
// residual; below the resonance that is close to the force itself. About
// 1/√N for a white residual.
SignatureValue polynomial_spring(const ResidualView& r) {
  const Eigen::VectorXd& y = r.y_model;
  Eigen::MatrixXd x(y.size(), 3);
  x.col(0) = y;
  x.col(1) = y.array().square().matrix();
  x.col(2) = y.array().cube().matrix();
  const double full = regress(r.e, x).r_squared;
  const double linear = regress(r.e, x.leftCols(1)).r_squared;
  if (!std::isfinite(full) || !std::isfinite(linear) || !(linear < 1.0)) return {};
  return {std::sqrt(std::max(0.0, full - linear) / (1.0 - linear))};
}

// The stiffness dF/dy = 1 + 2 k2 y + 3 k3 y^2 at ±kReadingStroke, as a
// multiple of the linear one: how hard and how lopsided the spring is over
// the record's strokes.
std::string stiffness_reading(double k2, double k3) {
  const double s = kReadingStroke;
  const double up = 1.0 + 2.0 * k2 * s + 3.0 * k3 * s * s, down = 1.0 - 2.0 * k2 * s + 3.0 * k3 * s * s;
  const std::string kind = (up + down) / 2.0 >= 1.0 ? "hardening" : "softening";
  return "is a " + kind + " spring (k2 = " + format_number("%.3g", k2) + ", k3 = " + format_number("%.3g", k3) +
         ", normalised): at twice the output's RMS its stiffness is " + format_number("%.3g", up) +
         " times the linear one above rest and " + format_number("%.3g", down) + " times below";
}

// The drag as a share of the linear damping at the speed of a stroke of one
// output RMS at the resonance (|y'/wn| = 1): drag / (2 zeta).
std::string drag_reading(double zeta, double drag) {
  return "a quadratic drag (" + format_number("%.3g", drag) + ", normalised) adds " +
         format_number("%.3g", 100.0 * drag / (2.0 * zeta)) +
         " % to the linear damping at the speed of a one-RMS stroke at the resonance";
}

std::string spring_reading(std::span<const double> p) {
  const double zeta = p[1], k2 = p[2], k3 = p[3], drag = p[4];
  const bool spring = k2 != 0.0 || k3 != 0.0;
  if (!spring && drag == 0.0) return "";
  if (!spring) return "is a linear spring with " + drag_reading(zeta, drag);
  if (drag == 0.0) return stiffness_reading(k2, k3);
  return stiffness_reading(k2, k3) + "; " + drag_reading(zeta, drag);
}

struct DuffingSpring {
  static EffectInfo info() {
    EffectInfo i;
    i.name = "duffing";
    i.summary =
        "Duffing oscillator: mass-spring-damper whose spring force y + k2 y² + k3 y³ hardens or "
        "softens with deflection, with a drag growing with the square of the speed";
    i.citation =
        "Kovacic & Brennan (eds.), The Duffing Equation, Wiley 2011; Wigren & Schoukens, Three free "
        "data sets for development and benchmarking in nonlinear identification, ECC 2013 (Silverbox)";
    i.stage = EffectStage::Dynamics;
    i.extends = "msd";
    // Bounds: at three times the output's RMS, about a record's largest
    // stroke, k3 = 1 makes the spring 28 times as stiff as at rest;
    // k3 = −0.2 lets a stroke of 1.3 RMS escape; k2 = ±1 alone lets one of
    // half an RMS escape on one side, and with k3 > k2²/3 the force rises
    // monotonically again. Wider boxes only sent the global searches into
    // stiffer oscillators, with more sub-steps.
    // A drag only takes energy out: drag >= 0. Allowed below 0, it stood in
    // for dry friction (a planted Coulomb force, tests/beyond_catalog.sh),
    // whose equivalent damping falls with the speed.
    i.params = oscillator_params({
        {"k2", -1.0, 1.0, 0.0, -1, 0, "",
         "quadratic stiffness relative to the linear one: an asymmetric spring (physical value in 1/output "
         "unit)"},
        {"k3", -0.2, 1.0, 0.0, -2, 0, "",
         "cubic stiffness relative to the linear one: > 0 hardening, < 0 softening (physical value in "
         "1/output unit²)"},
        {"drag", 0.0, 0.5, 0.0, -1, 0, "",
         "quadratic damping (y'/wn)|y'/wn| relative to the linear stiffness: a drag growing with the "
         "square of the speed (physical value in 1/output unit)"},
    });
    i.signature =
        "the error grows with amplitude near the resonance and the resonance moves with amplitude: a "
        "spring that stiffens or softens with deflection, the same at every drive rate";
    i.statistic = {"partial corr(e; ŷ², ŷ³ | ŷ)", polynomial_spring,
                   "the residual follows ŷ² and ŷ³ beyond what ŷ explains (partial r = {value})"};
    i.reading = spring_reading;
    return i;
  }

  // p = (k2, k3, drag). The sub-steps are sized for the linear spring: the
  // stiffness at a stroke depends on the normalisation (k3 is relative to
  // the output's RMS), and the physical output must not. Within the bounds
  // a spring at twice the RMS turns at most 3.6 times as fast (k3 = 1), 0.36
  // rad a sub-step; Silverbox's (k3 = 0.012) 1.07 times. The drag, in
  // samples: (y'/wn)|y'/wn| = v|v| / ws².
  static std::optional<OscillatorLaw> coefficients(std::span<const double> p, double ws) {
    const double k2 = p[0], k3 = p[1], drag = p[2];
    if (!std::isfinite(k2) || !std::isfinite(k3) || !std::isfinite(drag)) return std::nullopt;
    return OscillatorLaw{{k2, k3, drag / (ws * ws)}, 1.0, false};
  }

  // Spring force y + k2 y² + k3 y³ and drag.
  template <class V>
  static V excess(const OscillatorRates<V>& c, V w, V y, V v, V) {
    return w - y * (1.0 + y * (c.p0 + c.p1 * y)) - c.p2 * v * lane_abs(v);
  }

  template <class V>
  static V zdot(const OscillatorRates<V>&, V, V, V) {
    return V{};
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Oscillator<hystbench::DuffingSpring>)
