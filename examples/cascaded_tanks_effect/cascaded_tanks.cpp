// Two water tanks in cascade, the upper one overflowing: the physics of the
// cascaded-tanks benchmark (Schoukens, Mattsson, Wigren & Noël, 2016),
// written as a user's dynamics effect.
//
//   tau1·h1' = w − f1(h1) − overflow               upper tank, filled by the pump w
//   tau2·h2' = f1(h1) + spill·overflow − f2(h2)    lower tank, y = h2
//   fi(h) = sign(h)·|h|^alpha_i                     outflow through an orifice
//
// alpha = ½ is Torricelli's law (turbulent flow through an orifice), alpha
// = 1 laminar flow, which makes a tank a first-order lag. Each tank has its
// own exponent, and the box reaches down to 0.2: below ½ the exponent no
// longer describes an orifice but what the law leaves out of the level the
// sensor reads (its curve, a tank whose cross-section changes with height);
// on the measured tanks the best fits put the lower one near 0.2
// (docs/discovery.md, "Measured benchmarks"). The upper tank holds at most
// `capacity`: at the brim its level stops rising and the inflow it cannot
// pass on overflows, a share `spill` of it into the lower tank (the rest is
// lost). In steady state h2 = w^(1/alpha2): the static nonlinearity, and the
// model's gain scales the pump. The level sensor reads at most `ceiling`
// (the benchmark's clips at 10 V on both records); the water above it is
// still there and still drains.
//
// Levels are in normalised output units. The odd extension of f keeps the
// effect defined (and the neutral model exact) for a signal of either sign;
// below |h| = kLinearBelow, f is linear, so the ODE stays Lipschitz where
// Torricelli's f' is infinite and explicit RK4 does not ring as a tank empties.
//
// Parameters and their neutral values (at all of them y = w exactly):
//   log10_tau1, log10_tau2  log10 of the time scales in s, -1 = no tank (the
//                level follows its inflow at once). Time scales span four
//                decades; on a linear box the global searches spend their
//                samples on the top one and did not reach the measured
//                tanks' best basin (docs/discovery.md, "Measured benchmarks").
//   alpha1, alpha2  1
//   inv_capacity 1/capacity, 0 = the tank never overflows
//   spill        0 (a shape: it matters only while the tank overflows)
//   inv_ceiling  1/ceiling, 0 = the sensor never clips
// Inverse levels put "never" inside the box, as saturation's 1/L² does.
//
// Integration: RK4 with `substeps` steps per sample (4 by default), the
// input straight between samples (held under --input-hold zoh; a spline
// needs the whole record, and the tanks are far slower than a sample).
#include <algorithm>
#include <cmath>

#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

constexpr double kLinearBelow = 1e-3;
// The lower end of the log10 time scales: no tank (the level follows its
// inflow at once). Just above it a tank of 0.1 s is as good as none at the
// sampling of a tank's record, so the box has no gap at its end.
constexpr double kNoTank = -1.0;
constexpr int kDefaultSubsteps = 4;

double outflow(double h, double alpha) {
  const double a = std::abs(h);
  if (a < kLinearBelow) return h * std::pow(kLinearBelow, alpha - 1.0);
  return std::copysign(std::pow(a, alpha), h);
}

// The inverse of outflow: the level at which a tank passes q.
double level_for(double q, double alpha) {
  const double edge = std::pow(kLinearBelow, alpha);
  if (std::abs(q) < edge) return q / std::pow(kLinearBelow, alpha - 1.0);
  return std::copysign(std::pow(std::abs(q), 1.0 / alpha), q);
}

struct Tanks {
  double tau1, tau2, alpha1, alpha2, capacity, spill;
  bool upper, lower;  // false: that tank has tau 0 and is algebraic

  // Inflow to the lower tank and overflow from the upper one at level h1.
  void upper_flows(double w, double h1, double& q1, double& over) const {
    q1 = upper ? outflow(h1, alpha1) : w;
    over = upper && h1 >= capacity && w > q1 ? w - q1 : 0.0;
  }

  // d(h1, h2)/dt at inflow w.
  void rates(double w, double h1, double h2, double& d1, double& d2) const {
    double q1, over;
    upper_flows(w, h1, q1, over);
    d1 = upper ? (w - q1 - over) / tau1 : 0.0;
    d2 = lower ? (q1 + spill * over - outflow(h2, alpha2)) / tau2 : 0.0;
  }

  // One RK4 step of length dt from w0 to w1 (inflow at the step's ends).
  void step(double w0, double w1, double dt, double& h1, double& h2) const {
    const double wm = 0.5 * (w0 + w1);
    double a1, a2, b1, b2, c1, c2, d1, d2;
    rates(w0, h1, h2, a1, a2);
    rates(wm, h1 + 0.5 * dt * a1, h2 + 0.5 * dt * a2, b1, b2);
    rates(wm, h1 + 0.5 * dt * b1, h2 + 0.5 * dt * b2, c1, c2);
    rates(w1, h1 + dt * c1, h2 + dt * c2, d1, d2);
    h1 = std::min(h1 + dt / 6.0 * (a1 + 2.0 * b1 + 2.0 * c1 + d1), capacity);
    h2 += dt / 6.0 * (a2 + 2.0 * b2 + 2.0 * c2 + d2);
  }

  // The algebraic tanks' levels at inflow w.
  void settle(double w, double& h1, double& h2) const {
    if (!upper) h1 = w;
    if (lower) return;
    double q1, over;
    upper_flows(w, h1, q1, over);
    h2 = level_for(q1 + spill * over, alpha2);
  }
};

// Residual signature: the residual follows the output's square root beyond
// what the output explains (a tank's steady level goes as its inflow squared,
// so a linear model misses w^2 curvature); about 1/√N for a white residual.
hystbench::SignatureValue square_root_curvature(const hystbench::ResidualView& r) {
  const Eigen::VectorXd root = r.y_model.cwiseAbs().cwiseSqrt();
  return {hystbench::correlation(r.e, root - r.y_model * (root.dot(r.y_model) / r.y_model.squaredNorm()))};
}

class CascadedTanks : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "cascaded_tanks";
    i.summary = "two tanks in cascade with orifice outflow |h|^alpha, the upper one overflowing";
    i.citation =
        "Schoukens, Mattsson, Wigren & Noël, Cascaded tanks benchmark combining soft and hard "
        "nonlinearities, Workshop on Nonlinear System Identification Benchmarks, 2016";
    i.stage = hystbench::EffectStage::Dynamics;
    i.params = {{"log10_tau1", kNoTank, 3.0, kNoTank, 0, 0, "log10 s",
                 "upper tank's time scale tau1 = 10^log10_tau1 s, 0.1 s to 1000 s (-1 = no tank)"},
                {"log10_tau2", kNoTank, 3.0, kNoTank, 0, 0, "log10 s",
                 "lower tank's time scale tau2 = 10^log10_tau2 s, 0.1 s to 1000 s (-1 = no tank)"},
                {"alpha1", 0.2, 1.0, 1.0, 0, 0, "", "upper tank's outflow exponent (1/2: Torricelli, 1: linear)"},
                {"alpha2", 0.2, 1.0, 1.0, 0, 0, "", "lower tank's outflow exponent (1/2: Torricelli, 1: linear)"},
                {"inv_capacity", 0.0, 5.0, 0.0, 0, 0, "",
                 "1 / the upper tank's capacity, a normalised level (0 = never full)"},
                {"spill", 0.0, 1.0, 0.0, 0, 0, "", "share of the overflow that falls into the lower tank",
                 true},
                {"inv_ceiling", 0.0, 5.0, 0.0, 0, 0, "",
                 "1 / the highest level the sensor reads, a normalised level (0 = it never clips)"}};
    i.signature =
        "the output settles slowly and its steady level grows faster than the drive, as a tank's "
        "level grows with the square of its inflow";
    i.statistic = {"corr(e, √|ŷ| beyond ŷ)", square_root_curvature,
                   "the residual follows the square root of the model output beyond the output itself "
                   "(r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    for (double v : p)
      if (!std::isfinite(v)) return false;
    if (p[0] < kNoTank || p[1] < kNoTank || !(p[2] > 0.0) || !(p[3] > 0.0) || p[4] < 0.0 || p[6] < 0.0)
      return false;
    const auto inverse = [](double v) { return v > 0.0 ? 1.0 / v : INFINITY; };
    const auto tau = [](double q) { return q > kNoTank ? std::pow(10.0, q) : 0.0; };
    const Tanks t{tau(p[0]), tau(p[1]), p[2], p[3], inverse(p[4]), p[5], p[0] > kNoTank, p[1] > kNoTank};
    const double ceiling = inverse(p[6]);
    // Neutral: the upper exponent acts only in a tank.
    if (!t.upper && !t.lower && t.alpha2 == 1.0 && ceiling == INFINITY) return true;
    if ((t.upper || t.lower) && !(ctx.sample_time > 0.0)) return false;
    const int n = ctx.substeps > 0 ? ctx.substeps : kDefaultSubsteps;
    const double dt = ctx.sample_time / n;
    // From rest: both tanks empty.
    double h1 = 0.0, h2 = 0.0;
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      const double w0 = signal[k];
      t.settle(w0, h1, h2);
      signal[k] = std::min(h2, ceiling);  // the sensor clips; the level goes on
      if (k + 1 == signal.size()) break;
      const double w1 = ctx.hold == hystbench::InputHold::Zoh ? w0 : signal[k + 1];
      for (int s = 0; s < n; ++s)
        t.step(hystbench::held_value(hystbench::InputHold::Linear, w0, w1, double(s) / n),
               hystbench::held_value(hystbench::InputHold::Linear, w0, w1, double(s + 1) / n), dt, h1, h2);
    }
    return std::isfinite(h1) && std::isfinite(h2);
  }
};

}  // namespace

HYSTBENCH_EFFECT(CascadedTanks)
