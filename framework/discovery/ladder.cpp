#include "framework/discovery/ladder.hpp"

#include <optional>
#include <utility>

#include "framework/core/parallel_jobs.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/resonance.hpp"

namespace hystbench {
namespace {

struct Pruned {
  FitResult fit;
  std::vector<std::string> removed;
};

// One round of backward elimination: the best removal if it lowers the BIC.
std::optional<std::pair<std::string, FitResult>> best_removal(const FitResult& current,
                                                             const std::string& keep,
                                                             const ModelData& data,
                                                             const FitOptions& fit) {
  const long n = data.estimation_count();
  const double current_bic = bic(current.sse, n, current.model.dimension());
  const auto effects = current.model.effects();
  std::vector<std::optional<FitResult>> tried(effects.size());
  parallel_jobs(effects.size(), [&](std::size_t i) {
    if (effects[i] == keep) return;
    const Model smaller = current.model.without(effects[i]);
    tried[i] = refit_warm(smaller, data, smaller.carry_over(current.model, current.x), {}, fit);
  });
  std::optional<std::pair<std::string, FitResult>> best;
  double best_bic = current_bic;
  for (std::size_t i = 0; i < effects.size(); ++i) {
    if (!tried[i]) continue;
    const double b = bic(tried[i]->sse, n, tried[i]->model.dimension());
    if (b < best_bic) best_bic = b, best.emplace(effects[i], *tried[i]);
  }
  return best;
}

Pruned prune(FitResult current, const std::string& keep, const ModelData& data,
             const FitOptions& fit) {
  Pruned p{std::move(current), {}};
  while (auto removal = best_removal(p.fit, keep, data, fit)) {
    if (fit.status) fit.status("pruned " + removal->first);
    p.removed.push_back(removal->first);
    p.fit = std::move(removal->second);
  }
  return p;
}

LadderStep make_step(const Diagnosis& d) {
  LadderStep s{d.model, d.x, d.errors};
  s.bic = d.bic;
  return s;
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
  return "Adding " + w.effect + " made " + join(p.removed, ", ") +
         " redundant: removing it lowered the BIC, so it was dropped" +
         (shared.empty() ? "." : "; " + w.effect + " took over its role: " + shared + ".");
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
  Pruned p = prune(fitted, neutral ? std::string() : w.effect, data, refit);
  if (!p.removed.empty()) p.fit = fit_model(p.fit.model, data, refit, &p.fit.x);
  const bool dropped = !p.fit.model.has(w.effect);
  if (dropped) std::erase(p.removed, w.effect);
  LadderStep s{p.fit.model, p.fit.x, {}};
  s.added = w.effect;
  s.removed = p.removed;
  s.evidence = w.evidence;
  s.attribution = attribution(w, dropped, p, fitted, data.sample_time);
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
  LadderStep s = make_step(d);  // the diagnosis polished the fit: that fit is the rung
  s.added = next.added;
  s.removed = next.removed;
  s.evidence = next.evidence;
  s.attribution = next.attribution;
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
