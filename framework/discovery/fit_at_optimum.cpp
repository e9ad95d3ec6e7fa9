#include "framework/discovery/fit_at_optimum.hpp"

#include <cmath>
#include <set>

#include "framework/core/rng.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/completeness.hpp"
#include "framework/discovery/parameter_uncertainty.hpp"

namespace hystbench {
namespace {

std::string rmse_text(const FitErrors& e) {
  return format_number("%.4g", e.rmse_estimation) + " (held out " + format_number("%.4g", e.rmse_heldout) + ")";
}

// The effects owning the most correlated pair of parameters (not the gain).
std::vector<std::string> correlated_effects(const FitResult& fit, const ModelData& data,
                                            double& correlation, std::string& pair) {
  const ParameterUncertainty u = parameter_uncertainty(fit.model, fit.x, data);
  const auto [ij, value] = u.most_correlated();
  correlation = value;
  std::vector<std::string> out;
  if (ij.first < 0) return out;
  const auto names = fit.model.parameter_names();
  pair = names[ij.first] + " and " + names[ij.second];
  std::set<std::string> seen;
  for (int i : {ij.first, ij.second}) {
    const auto dot = names[i].find('.');
    if (dot != std::string::npos && seen.insert(names[i].substr(0, dot)).second)
      out.push_back(names[i].substr(0, dot));
  }
  return out;
}

}  // namespace

bool suspect_optimum(const FitErrors& e, double sigma, std::string& reason) {
  if (e.n_heldout == 0 || !e.stable) {
    reason = e.stable ? "no held-out data to check the fit against" : "the fit is unstable";
    return false;
  }
  const double gap = e.rmse_heldout / e.rmse_estimation;
  if (gap > kHeldoutGapRatio) {
    reason = "the held-out RMSE is " + format_number("%.3g", gap) + " times the estimation RMSE (above " +
             format_number("%.3g", kHeldoutGapRatio) + ")";
    return true;
  }
  if (sigma > 0 && e.rmse_estimation <= kFloorTolerance * sigma &&
      e.rmse_heldout > kFloorTolerance * sigma) {
    reason = "the estimation RMSE is at the noise estimate (" +
             format_number("%.3g", e.rmse_estimation / sigma) + " σ) but the held-out RMSE is not (" +
             format_number("%.3g", e.rmse_heldout / sigma) + " σ)";
    return true;
  }
  reason = "the held-out and estimation errors agree (ratio " + format_number("%.3g", gap) + ")";
  return false;
}

OptimumCheck ensure_optimum(FitResult& fit, const ModelData& data, double sigma,
                            const FitOptions& o) {
  OptimumCheck c;
  c.before = c.after = fit_errors(fit.model, fit.x, data);
  c.triggered = suspect_optimum(c.before, sigma, c.reason);
  if (!c.triggered) return c;
  auto consider = [&](FitResult other, const std::string& what) {
    const FitErrors e = fit_errors(other.model, other.x, data);
    const bool better = other.sse < fit.sse;
    c.actions.push_back(what + ": RMSE " + rmse_text(e) + (better ? ", kept" : ", not better"));
    if (better) fit = std::move(other), c.improved = true;
  };
  // Seeds of their own: the fit being checked already used the plain ones.
  FitOptions global = o;
  global.seed = trial_seed(o.seed, "optimum", 0);
  if (o.status) o.status("fit off its optimum? " + std::to_string(o.restarts) + " global restarts");
  consider(fit_model(fit.model, data, global),
           std::to_string(o.restarts) + " global restarts of " + fit.model.text());
  double correlation = 0;
  std::string pair;
  for (const auto& effect : correlated_effects(fit, data, correlation, pair)) {
    Eigen::VectorXd x0 = fit.x;
    const Eigen::VectorXd neutral = fit.model.neutral();
    const auto fresh = fit.model.parameters_of(effect);
    for (int i : fresh) x0[i] = neutral[i];
    if (o.status) o.status("fit off its optimum? " + effect + " searched again");
    consider(refit_warm(fit.model, data, x0, fresh, o),
             effect + " searched again from neutral (" + pair + " correlate at " +
                 format_number("%.3f", correlation) + ")");
  }
  c.after = fit_errors(fit.model, fit.x, data);
  return c;
}

OptimumCheck OptimumCheck::from_json(const nlohmann::json& j) {
  OptimumCheck c;
  c.triggered = j.at("triggered").get<bool>();
  c.reason = j.at("reason").get<std::string>();
  c.actions = j.at("actions").get<std::vector<std::string>>();
  c.improved = j.at("improved").get<bool>();
  c.before = FitErrors::from_json(j.at("before"));
  c.after = FitErrors::from_json(j.at("after"));
  return c;
}

nlohmann::json OptimumCheck::to_json() const {
  return {{"triggered", triggered},
          {"reason", reason},
          {"actions", actions},
          {"improved", improved},
          {"before", before.to_json()},
          {"after", after.to_json()}};
}

}  // namespace hystbench
