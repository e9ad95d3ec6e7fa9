#include "framework/discovery/ladder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "framework/core/text.hpp"
#include "framework/discovery/resonance.hpp"
#include "framework/discovery/separability.hpp"

namespace hystbench {
namespace {

// Where the role of a removed effect went: its resonance, now drawn by an
// effect of `after` within 10 % of its frequency (with the mode's physical
// reading), or a rival of the catalog that can carry it.
std::string role_passed(const std::string& removed, const FitResult& before, const FitResult& after,
                        double sample_time) {
  const auto was = resonances(before.model, before.x, sample_time);
  const auto now = resonances(after.model, after.x, sample_time);
  for (const auto& r : was) {
    if (r.effect != removed) continue;
    for (const auto& n : now)
      if (std::abs(n.hz - r.hz) <= 0.1 * r.hz)
        return " The resonance " + removed + " drew (" + format_number("%.4g", r.hz) + " Hz, peak gain " +
               format_number("%.3g", r.peak_gain) + ") is now carried by " + n.effect + " (" +
               format_number("%.4g", n.hz) + " Hz, peak gain " + format_number("%.3g", n.peak_gain) +
               ", damping ratio about " + format_number("%.2g", 0.5 / n.peak_gain) + ").";
  }
  const auto rivals = rivals_among(removed, after.model.effects());
  if (rivals.empty()) return "";
  return " The role of " + removed + " passed to " + join(rivals, " and ") + ".";
}

// Who gets the credit for the rung that adding `w` produced. `fitted`: the
// extended model before pruning.
std::string attribution(const Candidate& w, bool dropped, const Pruned& p,
                        const FitResult& fitted, double sample_time) {
  if (dropped)
    return w.effect + " stayed at its neutral value in the refit and was dropped again: the "
                      "error fell because the refit found a better fit of the other effects, not "
                      "because of " +
           w.effect + (p.removed.empty() ? "" : "; that refit made " + join(p.removed, ", ") +
                                                    " redundant") +
           ".";
  if (p.removed.empty()) return "";
  const std::string shared = shared_resonance(fitted.model, fitted.x, sample_time, w.effect);
  std::string passed;
  for (const auto& r : p.removed) passed += role_passed(r, fitted, p.fit, sample_time);
  return "Adding " + w.effect + " made " + join(p.removed, ", ") +
         " redundant: removing it lowered the BIC, so it was dropped" +
         (shared.empty() ? "." : "; " + w.effect + " took over its role: " + shared + ".") + passed;
}

// Why a start-model effect stays although BIC prefers the model without
// it: the data must say its contribution is zero (docs/discovery.md,
// "Pruning on evidence"). The last rung's record gives no such evidence when
// it cannot tell the effect from a rival in the model (separability.hpp) or
// while a start-up transient dominates the error (startup_transient.hpp);
// and a removal whose fit pins a parameter of the model that takes over on
// a bound is a takeover by a degenerate rival, not evidence, unless the
// effect was doing nothing (neutral within noise) anyway.
std::optional<std::string> takeover_on_bound(const std::string& effect, const FitResult& current,
                                             const FitResult& sub, const ModelData& data, const DiscoverOptions& o) {
  const auto before = parameters_on_bound(current.model, current.x);
  std::vector<std::string> pinned;
  for (const auto& name : parameters_on_bound(sub.model, sub.x))
    if (std::find(before.begin(), before.end(), name) == before.end()) pinned.push_back(name);
  if (pinned.empty()) return std::nullopt;
  if (check_model(current.model, current.x, data, o.diagnose.u_unit, o.diagnose.y_unit).neutral(effect))
    return std::nullopt;
  return "without it, " + join(pinned, ", ") + (pinned.size() == 1 ? " sits" : " sit") +
         " on a bound of the search range: its role passed to an effect that can draw it only at "
         "the edge of its physical range, which is a takeover, not evidence that " + effect + " is absent.";
}

KeepReason start_effect_keep_reason(const Ladder& ladder, const ModelData& data, const DiscoverOptions& o) {
  const auto start = ladder.steps.front().model.effects();
  const Comparison& where = ladder.diagnoses.back().where;
  return [start, &where, &data, &o](const std::string& effect, const FitResult& current,
                                    const FitResult& sub) -> std::optional<std::string> {
    if (std::find(start.begin(), start.end(), effect) == start.end()) return std::nullopt;
    const auto pairs = inseparable_from(effect, current.model.effects(), where.excitation);
    if (!pairs.empty()) return pairs.front().sentence(where.excitation);
    if (where.startup.dominates) return where.startup.sentence();
    return takeover_on_bound(effect, current, sub, data, o);
  };
}

// Why the start-model effects that BIC would have removed stayed.
std::string held_note(const std::vector<HeldEffect>& held) {
  std::string out;
  for (const auto& h : held)
    out += " BIC would remove " + h.effect + ", but it is in the start model and the data give no "
           "evidence of its absence: " + h.reason + " It was kept.";
  return out;
}

// The rung after the last diagnosis: its winner refitted (warm start and
// global restarts), then pruned.
LadderStep next_step(const Ladder& ladder, const ModelData& data, const DiscoverOptions& o) {
  const auto step = ladder.diagnoses.size() - 1;
  FitOptions refit = o.diagnose.fit;
  refit.restarts = o.refit_restarts;
  refit.seed = o.diagnose.fit.seed + std::uint64_t(step) + 1;
  const Candidate& w = *ladder.diagnoses.back().winner();
  const FitResult fitted = fit_model(w.model, data, refit, &w.x);
  // An added effect that looks neutral may be pruned like any other; if BIC
  // keeps it, it does contribute (its standard errors were only wide).
  const bool neutral =
      check_model(fitted.model, fitted.x, data, o.diagnose.u_unit, o.diagnose.y_unit).neutral(w.effect);
  Pruned p = prune(fitted, neutral ? std::string() : w.effect, data, refit,
                   start_effect_keep_reason(ladder, data, o));
  if (!p.removed.empty()) p.fit = fit_model(p.fit.model, data, refit, &p.fit.x);
  const bool dropped = !p.fit.model.has(w.effect);
  if (dropped) std::erase(p.removed, w.effect);
  LadderStep s{p.fit.model, p.fit.x, {}};
  s.added = w.effect;
  s.removed = p.removed;
  s.nesting = p.refits;
  s.sub_models = p.tried;
  s.evidence = w.evidence;
  s.attribution = attribution(w, dropped, p, fitted, data.sample_time) +
                  held_note(p.held);
  return s;
}

// Diagnoses `next` (the fit of a new rung) and appends the rung.
void climb(Ladder& ladder, const LadderStep& next, const ModelData& data, const DiscoverOptions& o,
           const LadderObserver& on_step) {
  // An effect dropped again right after it was added would only be found
  // again by the same diagnosis: it sits this rung out.
  DiagnoseOptions diagnose_options = o.diagnose;
  if (!next.added.empty() && !next.model.has(next.added))
    diagnose_options.exclude.push_back(next.added);
  Diagnosis d = diagnose(next.model, next.x, data, diagnose_options);
  LadderStep s = rung_of(d);  // the diagnosis polished the fit: that fit is the rung
  s.added = next.added;
  s.removed = next.removed;
  s.evidence = next.evidence;
  s.attribution = next.attribution;
  s.nesting = next.nesting;
  s.sub_models = next.sub_models;
  ladder.steps.push_back(std::move(s));
  ladder.diagnoses.push_back(std::move(d));
  if (on_step) on_step(ladder);
}

Ladder run(Ladder ladder, const ModelData& data, const DiscoverOptions& o,
           const LadderObserver& on_step) {
  while (!ladder.finished()) {
    if (int(ladder.diagnoses.size()) > o.max_steps) {
      ladder.stopped_by_limit = true;
      break;
    }
    climb(ladder, next_step(ladder, data, o), data, o, on_step);
  }
  return ladder;
}

}  // namespace

LadderStep rung_of(const Diagnosis& d) {
  LadderStep s{d.model, d.x, d.errors};
  s.bic = d.bic;
  return s;
}

bool Ladder::finished() const {
  return stopped_by_limit || (!diagnoses.empty() && diagnoses.back().winner() == nullptr);
}

Ladder discover(const Model& start, const ModelData& data, const DiscoverOptions& o,
                const LadderObserver& on_step) {
  Ladder ladder;
  const FitResult first = fit_model(start, data, o.diagnose.fit);
  climb(ladder, LadderStep{first.model, first.x, {}}, data, o, on_step);
  return run(std::move(ladder), data, o, on_step);
}

Ladder resume_discover(Ladder ladder, const ModelData& data, const DiscoverOptions& o,
                       const LadderObserver& on_step) {
  return run(std::move(ladder), data, o, on_step);
}

}  // namespace hystbench
