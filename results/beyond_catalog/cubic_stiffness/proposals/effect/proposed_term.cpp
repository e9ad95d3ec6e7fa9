// Proposed from data by `hystbench propose`: the term x³ at the dynamics stage,
// from the residual of the model hysteresis,asymmetry,msd,arx fitted to data.csv. It explained 93 %
// of what that fit left; proposed coefficient -0.0054537 ± 8.6e-05 (normalised units).
//
//   signal[k] += c·x³,   x' = (x[k] − x[k−1]) / Ts,   x'[0] = 0
//
// with x the resonance's own output (the force depends on the output it drives).
// c = 0 leaves the signal unchanged.
// Written as one per-sample kernel (framework/model/kernel_effect.hpp), which
// gives the effect its batched form: candidates are fitted a block at a time,
// as the catalog's effects are. Build: see docs/plugins.md (out of the tree: a
// shared library).
#include <array>
#include <cmath>
#include <span>
#include <numbers>

#include "problems/hammerstein/effects/biquad.hpp"
#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

using hystbench::LaneBits;
using hystbench::LaneVector;
using hystbench::lane_abs;

// √x, and whether every lane of a mask is set: for one candidate (double,
// bool) or a block (LaneVector, LaneBits).
double lane_sqrt(double x) { return std::sqrt(x); }
LaneVector lane_sqrt(LaneVector x) {
  for (int l = 0; l < hystbench::kEffectLanes; ++l) x[l] = std::sqrt(x[l]);
  return x;
}
bool lane_all(bool m) { return m; }
bool lane_all(LaneBits m) {
  for (int l = 0; l < hystbench::kEffectLanes; ++l)
    if (!m[l]) return false;
  return true;
}

// |a|^power (√|a| when root), times sign(a) when odd.
template <class V>
V factor(V a, int power, bool odd, bool root = false) {
  V m = V{} + 1.0;
  if (root && power > 0)
    m = lane_sqrt(lane_abs(a));
  else
    for (int i = 0; i < power; ++i) m *= lane_abs(a);
  if (odd && power > 0) m = a < V{} ? -m : (a > V{} ? m : V{});
  return m;
}

// The term of the block's own signal a and of b (unused: the term is of one signal).
template <class V>
V term(V a, V a_rate, [[maybe_unused]] V b, [[maybe_unused]] V b_rate) {
  return factor(a, 3, true) * factor(a_rate, 0, false);
}

// Residual signature: the residual follows the term, built from the model output.
hystbench::SignatureValue term_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd &a = r.y_model, &b = r.u;
  Eigen::VectorXd phi(a.size());
  double previous = a.size() ? a[0] : 0.0, b_previous = b.size() ? b[0] : 0.0;  // no rate before the record
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    phi[k] = term(a[k], (a[k] - previous) / r.sample_time, b[k], (b[k] - b_previous) / r.sample_time);
    previous = a[k], b_previous = b[k];
  }
  return {hystbench::correlation(r.e, phi)};
}

class ProposedTerm : public hystbench::KernelEffect<ProposedTerm, 6, hystbench::EffectDrive::None> {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "proposed_term";
    i.summary = "proposed from data: c·x³ at the dynamics stage";
    i.citation = "proposed from data by hystbench propose (data.csv, residual of hysteresis,asymmetry,msd,arx)";
    i.stage = hystbench::EffectStage::Dynamics;
    i.extends = "msd";
    i.params = {{"period", 0, 0.20000000000000001, 0, 0, 0, "s", "natural period 1/f_n (0 = infinitely stiff: no resonance)"},
                {"zeta", 0.0050000000000000001, 2, 0.5, 0, 0, "", "damping ratio"},
                {"c", -0.054536961736426505, 0.054536961736426505, 0, -2, 0, "", "coefficient of the proposed term"}};
    i.signature = "the residual follows x³";
    i.statistic = {"corr(e, x³)", term_correlation, "the residual follows x³ (r = {value})"};
    return i;
  }

  struct Aux {
    double ts;
  };
  static Aux aux(double ts) { return {ts}; }
  static constexpr bool kEarlyExit = true;

  // c = (g0, g1, g2, g3, g4, coefficient): G = 1 − H as msd, all 0 without a resonance.
  static hystbench::EffectSetup setup(std::span<const double> p, double ts, std::array<double, 6>& c) {
    const double period = p[0], zeta = p[1], coefficient = p[2];
    if (!std::isfinite(period) || !std::isfinite(zeta) || !std::isfinite(coefficient) || period < 0.0)
      return hystbench::EffectSetup::Invalid;
    if (!(ts > 0.0) || !std::isfinite(ts)) return hystbench::EffectSetup::Invalid;
    c = {0.0, 0.0, 0.0, 0.0, 0.0, coefficient};
    if (period == 0.0) return coefficient == 0.0 ? hystbench::EffectSetup::PassThrough : hystbench::EffectSetup::Run;
    if (!(zeta > 0.0)) return hystbench::EffectSetup::Invalid;
    const auto [k2, q, a0] = hystbench::tustin_resonance(period / (std::numbers::pi * ts), zeta);
    c = {(k2 + q) / a0, -2.0 * k2 / a0, (k2 - q) / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0, coefficient};
    if (!std::isfinite(c[3]) || !std::isfinite(c[4]) || !std::isfinite(c[0])) return hystbench::EffectSetup::Invalid;
    return hystbench::EffectSetup::Run;
  }

  template <class V>
  struct State {
    hystbench::BiquadState<V> resonance{};
    V x1{};      // the output one sample earlier
    V b1{};      // b one sample earlier
    V finite{};  // 0 while every output is finite and every force was solved
    bool started = false;  // no rate of b before the record
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 6>& c, const Aux& aux, State<V>& s, V w, [[maybe_unused]] Drive drive) {
    const std::array<V, 5> g = {c[0], c[1], c[2], c[3], c[4]};
    const V coefficient = c[5], one = V{} + 1.0;
    const V b = V{}, b_rate = s.started ? (b - s.b1) / aux.ts : V{};
    s.b1 = b, s.started = true;
    // The output for a given input of the resonance at this sample, its state left as it is.
    const auto output = [&](V input) {
      const V gw = ((g[0] * input + g[1] * s.resonance.w1) + (g[2] * s.resonance.w2 - g[4] * s.resonance.y2)) -
                   g[3] * s.resonance.y1;
      return input - gw;
    };
    // The force depends on the output it drives: x = output(w + c·term(x, (x − x1)/Ts, b, b')),
    // solved by Newton's method from the previous output, every lane on its own
    // (a lane stops when it has converged, or fails when it cannot).
    const auto residual = [&](V x) { return x - output(w + coefficient * term(x, (x - s.x1) / aux.ts, b, b_rate)); };
    V x = s.x1;
    auto done = coefficient == V{};  // no force: nothing to solve
    auto failed = coefficient != coefficient;  // none yet
    for (int i = 0; i < 12 && !lane_all(done); ++i) {
      const V f = residual(x), h = 1e-7 * (one < lane_abs(x) ? lane_abs(x) : one);
      const V slope = (residual(x + h) - f) / h;
      const auto broken = (f - f != V{}) | (slope - slope != V{}) | (slope == V{});
      const V step = f / slope, next = x - step;
      failed = done ? failed : (failed | broken);
      const auto close = lane_abs(step) <= 1e-12 * (one < lane_abs(next) ? lane_abs(next) : one);
      x = done ? x : next;
      done = done ? done : (close | broken);
    }
    failed = failed | (done == decltype(done){});  // no output consistent with its force: diverging
    const V force = coefficient == V{} ? V{} : coefficient * term(x, (x - s.x1) / aux.ts, b, b_rate);
    const V input = w + force;
    const V out = input - hystbench::biquad_step(g, s.resonance, input);
    s.x1 = out;
    s.finite = failed ? V{} + NAN : s.finite + out * 0.0;
    return out;
  }

  template <class V>
  static V health(const std::array<V, 6>&, const State<V>& s) {
    return s.finite;
  }
};
}  // namespace

HYSTBENCH_EFFECT(ProposedTerm)
