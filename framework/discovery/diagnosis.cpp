#include "framework/discovery/diagnosis.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

#include "framework/discovery/comparison.hpp"
#include "framework/discovery/evidence.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_comparison.hpp"

namespace hystbench {
namespace {

std::vector<std::string> candidate_effects(const Model& model, const DiagnoseOptions& o) {
  std::vector<std::string> all = o.candidates;
  if (all.empty())
    for (const auto* info : EffectRegistry::instance().all()) all.push_back(info->name);
  std::vector<std::string> out;
  for (const auto& name : all)
    if (!model.has(name)) out.push_back(name);
  return out;
}

ComparisonInput current_comparison(const Model& model, const Eigen::VectorXd& x,
                                   const ModelData& data, const DiagnoseOptions& o) {
  Eigen::VectorXd y;
  if (!simulate_physical(model, x, data, y)) y = Eigen::VectorXd::Zero(data.size());
  return comparison_input(data, std::move(y), o.u_unit, o.y_unit);
}

// Linear blocks in series trade a resonance among themselves (a fitted
// chain often splits it between msd and arx), so a new dynamics effect also
// gets a start in which the other dynamics effects pass the signal through
// and it has to explain the dynamics alone.
std::optional<Eigen::VectorXd> dynamics_reset_start(const Model& extended, const std::string& effect,
                                                    Eigen::VectorXd x0) {
  const auto& registry = EffectRegistry::instance();
  if (registry.find(effect, "effect").stage != EffectStage::Dynamics) return std::nullopt;
  const Eigen::VectorXd neutral = extended.neutral();
  bool changed = false;
  for (const auto& other : extended.effects()) {
    if (other == effect || registry.find(other, "effect").stage != EffectStage::Dynamics) continue;
    for (int i : extended.parameters_of(other)) x0[i] = neutral[i];
    changed = true;
  }
  return changed ? std::optional<Eigen::VectorXd>(x0) : std::nullopt;
}

// A residual that is white and uncorrelated with the input says the current
// basin already explains the data: a global restart could only rediscover it,
// so candidates skip theirs (the most expensive part of a diagnosis).
// Up to 2 of the ~51 cross-correlation lags may leave their 99 % band by
// chance (binomial tail 1.4 %).
bool residual_is_white(const Diagnosis& current) {
  const nlohmann::json& r = current.where.value("residual", nlohmann::json::object());
  if (!r.value("white", false)) return false;
  const nlohmann::json& ccf = r.value("ccf", nlohmann::json::object());
  return ccf.value("outside", 1 << 30) <= 2;
}

FitResult refit_candidate(const Model& extended, const std::string& effect, const Diagnosis& current,
                          const ModelData& data, const DiagnoseOptions& o) {
  const Eigen::VectorXd x0 = extended.carry_over(current.model, current.x);
  const auto fresh = extended.parameters_of(effect);
  FitResult best = refit_warm(extended, data, x0, fresh, o.fit);
  auto keep_better = [&](FitResult other) {
    if (other.sse < best.sse) best = std::move(other);
  };
  if (const auto reset = dynamics_reset_start(extended, effect, x0))
    keep_better(refit_warm(extended, data, *reset, fresh, o.fit));
  if (o.candidate_restarts > 0 && !residual_is_white(current)) {
    FitOptions global = o.fit;
    global.restarts = o.candidate_restarts;
    global.status = nullptr;  // candidates run in parallel: one status line is enough
    keep_better(fit_model(extended, data, global));
  }
  return best;
}

Candidate try_candidate(const std::string& effect, const Diagnosis& current, const ModelData& data,
                        const DiagnoseOptions& o) {
  const Model extended = current.model.with(effect);
  const FitResult r = refit_candidate(extended, effect, current, data, o);
  Candidate c{effect, extended, r.x, fit_errors(extended, r.x, data)};
  c.delta_k = extended.dimension() - current.model.dimension();
  const long n = current.errors.n_estimation;
  c.delta_bic = bic(c.after.sse, n, extended.dimension()) - current.bic;
  const bool heldout_ok = current.errors.n_heldout == 0 ||
                          c.after.rmse_heldout <= (1.0 - o.heldout_gain) * current.errors.rmse_heldout;
  c.significant = c.after.stable && c.delta_bic <= o.bic_threshold && heldout_ok;
  c.evidence = evidence_sentence(EffectRegistry::instance().find(effect, "effect"),
                                 signature_in(current.where, effect),
                                 current.errors, c.after, c.delta_bic, c.significant, o.y_unit);
  return c;
}

}  // namespace

double bic(double sse, long n, int k) {
  return double(n) * std::log(std::max(sse, 1e-300) / double(n)) + double(k) * std::log(double(n));
}

nlohmann::json DiagnoseOptions::to_json() const {
  return {{"fit", fit.to_json()},
          {"candidates", candidates},
          {"bic_threshold", bic_threshold},
          {"candidate_restarts", candidate_restarts},
          {"heldout_gain", heldout_gain}};
}

const Candidate* Diagnosis::winner() const {
  if (verdict == "none") return nullptr;
  for (const auto& c : candidates)
    if (c.effect == verdict) return &c;
  return nullptr;
}

Diagnosis diagnose(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                   const DiagnoseOptions& o) {
  if (o.fit.status) o.fit.status("polishing " + model.text());
  const FitResult polished = refit_warm(model, data, x, {}, o.fit);
  Diagnosis d{polished.model, polished.x, fit_errors(polished.model, polished.x, data)};
  d.bic = bic(d.errors.sse, d.errors.n_estimation, model.dimension());
  d.where = compare_signals(current_comparison(d.model, d.x, data, o));
  d.options = o.to_json();
  const auto effects = candidate_effects(model, o);
  std::vector<std::optional<Candidate>> tried(effects.size());
  std::vector<std::exception_ptr> failed(effects.size());
  long done = 0;
  omp_set_max_active_levels(2);
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < effects.size(); ++i) {
    // An exception must not leave an OpenMP region: it is rethrown below.
    try {
      tried[i] = try_candidate(effects[i], d, data, o);
    } catch (...) {
      failed[i] = std::current_exception();
    }
#pragma omp critical(diagnosis_status)
    if (o.fit.status)
      o.fit.status("candidates " + std::to_string(++done) + "/" + std::to_string(effects.size()) +
                   " (" + effects[i] + " done)");
  }
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  for (auto& c : tried) d.candidates.push_back(std::move(*c));
  std::stable_sort(d.candidates.begin(), d.candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.significant != b.significant) return a.significant;
    return a.delta_bic < b.delta_bic;
  });
  d.verdict = !d.candidates.empty() && d.candidates.front().significant ? d.candidates.front().effect
                                                                        : "none";
  return d;
}

nlohmann::json Diagnosis::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : candidates)
    list.push_back({{"effect", c.effect},
                    {"model", c.model.text()},
                    {"delta_k", c.delta_k},
                    {"delta_bic", std::isfinite(c.delta_bic) ? nlohmann::json(c.delta_bic) : nlohmann::json()},
                    {"significant", c.significant},
                    {"rmse_before", errors.rmse_estimation},
                    {"rmse_after", c.after.to_json()["rmse"]},
                    {"heldout_rmse_before", errors.n_heldout ? nlohmann::json(errors.rmse_heldout) : nlohmann::json()},
                    {"heldout_rmse_after", c.after.to_json()["heldout_rmse"]},
                    {"evidence", c.evidence}});
  return {{"verdict", verdict},
          {"model", model.text()},
          {"errors", errors.to_json()},
          {"bic", bic},
          {"candidates", list},
          {"where", where},
          {"options", options}};
}

}  // namespace hystbench
