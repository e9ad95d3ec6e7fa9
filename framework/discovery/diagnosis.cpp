#include "framework/discovery/diagnosis.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>

#include "framework/core/parallel_jobs.hpp"
#include "framework/core/rng.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/comparison.hpp"
#include "framework/discovery/evidence.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/discovery/resonance.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

// Whether the model already holds the role `name` would take: an effect
// that extends it (msd, once duffing replaced it), or another extension of
// the same base (feedback_hysteresis beside duffing). Model::with would put
// either in series with the one there, a second resonance, which is
// second_mode's role; fitting it only cost a candidate fit at every rung
// (on Silverbox two of twelve, among the slowest). Candidates the user
// names are tried as named.
bool role_taken(const Model& model, const std::string& name) {
  const auto& registry = EffectRegistry::instance();
  const std::string& base = registry.find(name, "effect").extends;
  for (const auto& other : model.effects()) {
    const std::string& other_base = registry.find(other, "effect").extends;
    if (other_base == name || (!base.empty() && other_base == base)) return true;
  }
  return false;
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
  // A residual that is white and uncorrelated with the input says the current
  // basin already explains the data: a global restart could only rediscover
  // it, so candidates skip theirs (the most expensive part of a diagnosis).
  if (o.candidate_restarts > 0 && !current.completeness.white) {
    FitOptions global = o.fit;
    global.restarts = o.candidate_restarts;
    global.status = nullptr;  // candidates run in parallel: one status line is enough
    keep_better(fit_model(extended, data, global));
  }
  return best;
}

// The candidate judged from its fit: ΔBIC, significance, fitted
// parameters and the evidence sentence.
Candidate judge_candidate(const std::string& effect, const FitResult& r, const Diagnosis& current,
                          const ModelData& data, const DiagnoseOptions& o) {
  const Model& extended = r.model;
  Candidate c{effect, extended, r.x, fit_errors(extended, r.x, data)};
  c.delta_k = extended.dimension() - current.model.dimension();
  const long n = current.errors.n_estimation;
  c.delta_bic = bic(c.after.sse, n, extended.dimension()) - current.bic;
  const bool heldout_ok = current.errors.n_heldout == 0 ||
                          c.after.rmse_heldout <= (1.0 - o.heldout_gain) * current.errors.rmse_heldout;
  c.significant = c.after.stable && c.delta_bic <= o.bic_threshold && heldout_ok;
  // A dynamics effect fitted onto a resonance the model already has only
  // re-describes that mode; it is shown but never the verdict.
  const auto shared = shared_resonance(extended, r.x, data.sample_time, effect);
  if (!shared.empty()) c.significant = false;
  c.check = check_model(extended, r.x, data, o.u_unit, o.y_unit);
  c.evidence = evidence_sentence(EffectRegistry::instance().find(effect, "effect"),
                                 signature_in(current.where.signatures, effect),
                                 current.errors, c.after, c.delta_bic, c.significant, o.y_unit);
  if (!shared.empty()) c.evidence += " Not counted: " + shared + ".";
  if (const std::string reading = c.check.reading(effect); !reading.empty()) c.evidence += " " + reading;
  const ExcitationContent& excitation = current.where.excitation;
  for (const auto& p : inseparable_from(effect, current.model.effects(), excitation))
    c.evidence += " " + p.sentence(excitation);
  return c;
}

Candidate try_candidate(const std::string& effect, const Diagnosis& current, const ModelData& data,
                        const DiagnoseOptions& o) {
  const Model extended = current.model.with(effect);
  return judge_candidate(effect, refit_candidate(extended, effect, current, data, o), current, data, o);
}

}  // namespace

std::vector<std::string> candidate_effects(const Model& model, const DiagnoseOptions& o) {
  std::vector<std::string> all = o.candidates;
  const bool whole_catalog = all.empty();
  if (whole_catalog)
    for (const auto* info : EffectRegistry::instance().all()) all.push_back(info->name);
  std::vector<std::string> out;
  for (const auto& name : all)
    if (!model.has(name) && !(whole_catalog && role_taken(model, name)) &&
        std::find(o.exclude.begin(), o.exclude.end(), name) == o.exclude.end())
      out.push_back(name);
  return out;
}

double bic(double sse, long n, int k) {
  return double(n) * std::log(std::max(sse, 1e-300) / double(n)) + double(k) * std::log(double(n));
}

nlohmann::json DiagnoseOptions::to_json() const {
  return {{"fit", fit.to_json()},
          {"candidates", candidates},
          {"bic_threshold", bic_threshold},
          {"candidate_restarts", candidate_restarts},
          {"heldout_gain", heldout_gain},
          {"close_margin", close_margin}};
}

const Candidate* Diagnosis::find(const std::string& effect) const {
  for (const auto& c : candidates)
    if (c.effect == effect) return &c;
  return nullptr;
}

const Candidate* Diagnosis::winner() const { return verdict == "none" ? nullptr : find(verdict); }

namespace {

// The current fit, polished and checked for being at its optimum, with its
// residual analysis.
Diagnosis current_fit(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                      const DiagnoseOptions& o) {
  if (o.fit.status) o.fit.status("polishing " + model.text());
  FitResult fit = refit_warm(model, data, x, {}, o.fit);
  Comparison where = compare_signals(current_comparison(fit.model, fit.x, data, o));
  const OptimumCheck optimum = ensure_optimum(fit, data, where.noise_floor.sigma, o.fit);
  if (optimum.improved) where = compare_signals(current_comparison(fit.model, fit.x, data, o));
  Diagnosis d{fit.model, fit.x, fit_errors(fit.model, fit.x, data)};
  d.bic = bic(d.errors.sse, d.errors.n_estimation, model.dimension());
  d.where = std::move(where);
  d.optimum = optimum;
  d.completeness = assess_completeness(d.errors, d.where);
  d.check = check_model(d.model, d.x, data, o.u_unit, o.y_unit);
  d.options = o.to_json();
  return d;
}

// "candidate 3 of 10 done (msd); best so far arx, ΔBIC −1234; about 40 s left"
struct CandidateProgress {
  std::size_t total;
  std::size_t finished = 0;
  std::string best_effect = {};
  double best_bic = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  std::string done(const std::string& effect, const Candidate* c) {
    ++finished;
    if (c && c->delta_bic < best_bic) best_bic = c->delta_bic, best_effect = effect;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = elapsed / double(finished) * double(total - finished);
    std::string s = "candidate " + std::to_string(finished) + " of " + std::to_string(total) +
                    " done (" + effect + ")";
    if (!best_effect.empty())
      s += "; best so far " + best_effect + ", ΔBIC " + format_number("%.0f", best_bic);
    if (finished < total) s += "; about " + format_number("%.0f", left) + " s left in this step";
    return s;
  }
};

void sort_candidates(std::vector<Candidate>& candidates) {
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.significant != b.significant) return a.significant;
    return a.delta_bic < b.delta_bic;
  });
}

std::vector<Candidate> try_candidates(const Diagnosis& d, const ModelData& data,
                                      const DiagnoseOptions& o) {
  const auto effects = candidate_effects(d.model, o);
  std::vector<std::optional<Candidate>> tried(effects.size());
  std::exception_ptr status_failed;
  CandidateProgress progress{effects.size()};
  omp_set_max_active_levels(2);
  parallel_jobs(effects.size(), [&](std::size_t i) {
    tried[i] = try_candidate(effects[i], d, data, o);
    // No exception may leave the critical section either.
#pragma omp critical(diagnosis_status)
    try {
      if (o.fit.status) o.fit.status(progress.done(effects[i], &*tried[i]));
    } catch (...) {
      status_failed = std::current_exception();
    }
  });
  if (status_failed) std::rethrow_exception(status_failed);
  std::vector<Candidate> out;
  for (auto& c : tried) out.push_back(std::move(*c));
  sort_candidates(out);
  return out;
}

// The verdict rests on the leading candidates' fits, and a warm refit plus
// `candidate_restarts` global restarts can leave a candidate in a poorer
// basin when its effect trades against one the model has (an input delay
// against the ARX block's lag lands a fraction of a sample off, with the
// ARX coefficients bent to match). So the two candidates with the lowest
// ΔBIC get a plain fit's global restarts, with seeds of their own, and keep
// the better fit before the verdict, unless no candidate comes near what
// the partial-help rule asks (refit_could_pass, beyond_catalog.hpp).
void refit_leaders(Diagnosis& d, const ModelData& data, const DiagnoseOptions& o) {
  if (o.fit.restarts == 0 || d.completeness.white) return;
  std::vector<Candidate*> leaders;
  for (auto& c : d.candidates)
    if (std::isfinite(c.delta_bic) && c.delta_bic <= o.bic_threshold) leaders.push_back(&c);
  std::sort(leaders.begin(), leaders.end(),
            [](const Candidate* a, const Candidate* b) { return a->delta_bic < b->delta_bic; });
  if (leaders.size() > 2) leaders.resize(2);
  if (leaders.empty()) return;
  if (!refit_could_pass(d)) return;
  std::string names;
  for (const auto* c : leaders) names += (names.empty() ? "" : ", ") + c->effect;
  if (o.fit.status)
    o.fit.status("refitting the leading candidates (" + names + ") with " +
                 std::to_string(o.fit.restarts) + " global restarts each");
  parallel_jobs(leaders.size(), [&](std::size_t i) {
    Candidate& c = *leaders[i];
    FitOptions global = o.fit;
    global.seed = trial_seed(o.fit.seed, "leading candidate", 0);
    global.status = nullptr;
    const FitResult r = fit_model(c.model, data, global, &c.x);
    if (fit_errors(r.model, r.x, data).sse < c.after.sse) c = judge_candidate(c.effect, r, d, data, o);
  });
  sort_candidates(d.candidates);
}

}  // namespace

namespace {

// The partial-help rule (beyond_catalog.hpp): above the noise floor, a
// winner that removes less than kPartialShare of the excess is not added.
bool refuse_partial(Diagnosis& d) {
  if (d.completeness.kind != "systematic") return false;
  const double share = candidate_share(d, d.verdict);
  if (!(share < kPartialShare)) return false;
  d.beyond.refused = d.verdict;
  d.beyond.refused_share = share;
  d.beyond.judged_on = d.errors.n_heldout > 0 ? "held-out" : "estimation";
  d.verdict = "none";
  return true;
}

}  // namespace

void decide(Diagnosis& d, const DiagnoseOptions& o) {
  d.close_call = {};
  d.beyond = {};
  std::vector<const Candidate*> significant;
  for (const auto& c : d.candidates)
    if (c.significant) significant.push_back(&c);
  if (significant.empty()) {
    d.verdict = "none";
    return;
  }
  const Candidate* by_bic = significant.front();  // candidates are sorted by ΔBIC
  const Candidate* by_heldout = by_bic;
  for (const auto* c : significant)
    if (c->after.rmse_heldout < by_heldout->after.rmse_heldout) by_heldout = c;
  const bool heldout_decides =
      d.errors.n_heldout > 0 && by_heldout != by_bic &&
      by_heldout->after.rmse_heldout <= (1.0 - o.heldout_gain) * by_bic->after.rmse_heldout;
  d.verdict = heldout_decides ? by_heldout->effect : by_bic->effect;
  if (refuse_partial(d)) return;
  if (d.errors.n_heldout > 0 && by_heldout != by_bic) {
    d.close_call = {true,
                    "BIC prefers " + by_bic->effect + " (ΔBIC " + format_number("%.1f", by_bic->delta_bic) +
                        " against " + format_number("%.1f", by_heldout->delta_bic) + "), the held-out RMSE " +
                        "prefers " + by_heldout->effect + " (" +
                        format_number("%.4g", by_heldout->after.rmse_heldout) + " against " +
                        format_number("%.4g", by_bic->after.rmse_heldout) + "); " +
                        (heldout_decides ? "the held-out error decides (it is at least " +
                                               format_number("%.0f", 100 * o.heldout_gain) + " % lower)"
                                         : "BIC decides (the held-out errors differ by less than " +
                                               format_number("%.0f", 100 * o.heldout_gain) + " %)"),
                    heldout_decides ? by_bic->effect : by_heldout->effect};
    return;
  }
  if (significant.size() > 1 && significant[1]->delta_bic - by_bic->delta_bic < o.close_margin)
    d.close_call = {true,
                    "the runner-up " + significant[1]->effect + " is within " +
                        format_number("%.0f", o.close_margin) + " of the winner's ΔBIC (" +
                        format_number("%.1f", significant[1]->delta_bic) + " against " +
                        format_number("%.1f", by_bic->delta_bic) +
                        ") and does not have the better held-out RMSE; BIC decides",
                    significant[1]->effect};
}

Diagnosis diagnose(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                   const DiagnoseOptions& o) {
  Diagnosis d = current_fit(model, x, data, o);
  d.candidates = try_candidates(d, data, o);
  refit_leaders(d, data, o);
  decide(d, o);
  describe_beyond_catalog(d, data);
  return d;
}

nlohmann::json Diagnosis::to_json() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : candidates)
    list.push_back({{"effect", c.effect},
                    {"model", c.model.text()},
                    {"delta_k", c.delta_k},
                    {"delta_bic", number_or_null(c.delta_bic)},
                    {"significant", c.significant},
                    {"rmse_before", number_or_null(errors.rmse_estimation)},
                    {"rmse_after", c.after.to_json()["rmse"]},
                    {"heldout_rmse_before", errors.n_heldout ? number_or_null(errors.rmse_heldout) : nlohmann::json()},
                    {"heldout_rmse_after", c.after.to_json()["heldout_rmse"]},
                    {"evidence", c.evidence},
                    {"parameters", c.check.to_json()}});
  return {{"verdict", verdict},
          {"complete", completeness.complete},
          {"completeness", completeness.to_json()},
          {"close_call", {{"close", close_call.close},
                          {"reason", close_call.reason},
                          {"runner_up", close_call.runner_up}}},
          {"optimum", optimum.to_json()},
          {"parameters", check.to_json()},
          {"model", model.text()},
          {"errors", errors.to_json()},
          {"bic", bic},
          {"candidates", list},
          {"where", hystbench::to_json(where)},
          {"beyond_catalog", beyond.to_json()},
          {"options", options}};
}

}  // namespace hystbench
