// Proposed from data by `hystbench propose`: the term y²·y' at the output stage,
// from the residual of the model duffing,offset fitted to estimation.csv. It explained 5.39 %
// of what that fit left; proposed coefficient -2.02996e-06 ± 2.7e-08 (normalised units).
//
//   signal[k] += c·y²·y',   y' = (y[k] − y[k−1]) / Ts,   y'[0] = 0
//
// with y the dynamics' output (the stage input).
// c = 0 leaves the signal unchanged.
// Written as one per-sample kernel (framework/model/kernel_effect.hpp), which
// gives the effect its batched form: candidates are fitted a block at a time,
// as the catalog's effects are. Build: see docs/plugins.md (out of the tree: a
// shared library).
#include <array>
#include <cmath>
#include <span>

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
  return factor(a, 2, false) * factor(a_rate, 1, true);
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

class ProposedTerm : public hystbench::KernelEffect<ProposedTerm, 1, hystbench::EffectDrive::StageInput> {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "proposed_term";
    i.summary = "proposed from data: c·y²·y' at the output stage";
    i.citation = "proposed from data by hystbench propose (estimation.csv, residual of duffing,offset)";
    i.stage = hystbench::EffectStage::Output;
    i.params = {{"c", -2.0299633566692216e-05, 2.0299633566692216e-05, 0, -2, 0, "s", "coefficient of the proposed term"}};
    i.signature = "the residual follows y²·y'";
    i.statistic = {"corr(e, y²·y')", term_correlation, "the residual follows y²·y' (r = {value})"};
    return i;
  }

  struct Aux {
    double ts;
  };
  static Aux aux(double ts) { return {ts}; }
  static constexpr bool kEarlyExit = true;

  static hystbench::EffectSetup setup(std::span<const double> p, double ts, std::array<double, 1>& c) {
    if (!std::isfinite(p[0]) || !(ts > 0.0)) return hystbench::EffectSetup::Invalid;
    if (p[0] == 0.0) return hystbench::EffectSetup::PassThrough;  // neutral: the signal as it was
    c = {p[0]};
    return hystbench::EffectSetup::Run;
  }

  template <class V>
  struct State {
    V previous{}, b_previous{};
    V finite{};  // 0 while every output is finite
    bool started = false;  // no rate before the record
  };

  template <class V, class Drive>
  static V sample(const std::array<V, 1>& c, const Aux& aux, State<V>& s, V signal, [[maybe_unused]] Drive drive) {
    const V a = drive, b = V{};
    const V rate = s.started ? (a - s.previous) / aux.ts : V{};
    const V b_rate = s.started ? (b - s.b_previous) / aux.ts : V{};
    s.previous = a, s.b_previous = b;
    s.started = true;
    const V out = signal + c[0] * term(a, rate, b, b_rate);
    s.finite += out * 0.0;
    return out;
  }

  template <class V>
  static V health(const std::array<V, 1>&, const State<V>& s) {
    return s.finite;
  }
};
}  // namespace

HYSTBENCH_EFFECT(ProposedTerm)
