// Proposed from data by `hystbench propose`: the term v·|v'| at the static stage,
// from the residual of the model hysteresis,asymmetry,msd,arx fitted to data.csv. It explained 97.3 %
// of what that fit left; proposed coefficient 0.000400387 ± 6.8e-07 (normalised units).
//
//   signal[k] += c·v·|v'|,   v' = (v[k] − v[k−1]) / Ts,   v'[0] = 0
//
// with v the drive (the stage input). c = 0 leaves the signal unchanged.
// Build: see docs/plugins.md (out of the tree: a shared library).
#include <cmath>

#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace {

// |a|^power, times sign(a) when odd.
double factor(double a, int power, bool odd) {
  double m = 1.0;
  for (int i = 0; i < power; ++i) m *= std::abs(a);
  if (odd && power > 0) m = a < 0 ? -m : (a > 0 ? m : 0.0);
  return m;
}

double term(double a, double a_rate) {
  return factor(a, 1, true) * factor(a_rate, 1, false);
}

// Residual signature: the residual follows the term, built from the input u.
hystbench::SignatureValue term_correlation(const hystbench::ResidualView& r) {
  const Eigen::VectorXd& a = r.u;
  Eigen::VectorXd phi(a.size());
  double previous = a.size() ? a[0] : 0.0;  // no rate before the record
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    phi[k] = term(a[k], (a[k] - previous) / r.sample_time);
    previous = a[k];
  }
  return {hystbench::correlation(r.e, phi)};
}

class ProposedTerm : public hystbench::Effect {
 public:
  static hystbench::EffectInfo info() {
    hystbench::EffectInfo i;
    i.name = "proposed_term";
    i.summary = "proposed from data: c·v·|v'| at the static stage";
    i.citation = "proposed from data by hystbench propose (data.csv, residual of hysteresis,asymmetry,msd,arx)";
    i.stage = hystbench::EffectStage::Nonlinearity;
    i.params = {{"c", -0.0040038710310089107, 0.0040038710310089107, 0, 1, -2, "s", "coefficient of the proposed term"}};
    i.signature = "the residual follows v·|v'|";
    i.statistic = {"corr(e, v·|v'|)", term_correlation, "the residual follows v·|v'| (r = {value})"};
    return i;
  }

  bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double c = p[0];
    if (!std::isfinite(c)) return false;
    if (c == 0.0) return true;  // neutral: the signal is left exactly as it was
    if (!(ctx.sample_time > 0.0) || !ctx.stage_input || ctx.stage_input->size() != signal.size()) return false;
    const Eigen::VectorXd& a = *ctx.stage_input;
    double previous = a.size() ? a[0] : 0.0;  // no rate before the record
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      signal[k] += c * term(a[k], (a[k] - previous) / ctx.sample_time);
      previous = a[k];
    }
    return signal.allFinite();
  }
};
}  // namespace

HYSTBENCH_EFFECT(ProposedTerm)
