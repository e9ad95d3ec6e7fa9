#include "framework/discovery/pruning.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "framework/core/parallel_jobs.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/diagnosis.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

struct Round {
  std::vector<std::string> effects;        // removed in turn
  std::vector<std::optional<FitResult>> fits;  // empty where the effect was kept
};

Round try_removals(const FitResult& current, const std::string& keep, const ModelData& data,
                   const FitOptions& fit) {
  Round r{current.model.effects(), {}};
  r.fits.resize(r.effects.size());
  parallel_jobs(r.effects.size(), [&](std::size_t i) {
    if (r.effects[i] == keep) return;
    const Model smaller = current.model.without(r.effects[i]);
    r.fits[i] = refit_warm(smaller, data, smaller.carry_over(current.model, current.x), {}, fit);
  });
  return r;
}

// The nesting rule: when a sub-model of the round fits better than
// `current`, `current` is refitted from the best one's optimum (its removed
// effect neutral, then searched again). Never worse than that sub-model.
std::optional<NestingRefit> lift(FitResult& current, const Round& r, const ModelData& data,
                                 const FitOptions& fit) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < r.fits.size(); ++i)
    if (r.fits[i] && r.fits[i]->sse < current.sse * (1.0 - kNestingTolerance) &&
        (!best || r.fits[i]->sse < r.fits[*best]->sse))
      best = i;
  if (!best) return std::nullopt;
  const FitResult& sub = *r.fits[*best];
  if (fit.status) fit.status("refitting " + current.model.text() + " from the better fit of " + sub.model.text());
  const Eigen::VectorXd x0 = current.model.carry_over(sub.model, sub.x);
  FitResult lifted = refit_warm(current.model, data, x0, current.model.parameters_of(r.effects[*best]), fit);
  NestingRefit n{current.model.text(), sub.model.text(), current.sse, sub.sse, lifted.sse};
  current = std::move(lifted);
  return n;
}

// The removal with the lowest BIC among those `allowed`, if it is below the
// current model's.
template <class Allowed>
std::optional<std::size_t> best_removal(const FitResult& current, const Round& r, const ModelData& data,
                                        Allowed allowed) {
  const long n = data.estimation_count();
  double best_bic = bic(current.sse, n, current.model.dimension());
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    if (!r.fits[i] || !allowed(i)) continue;
    const double b = bic(r.fits[i]->sse, n, r.fits[i]->model.dimension());
    if (b < best_bic) best_bic = b, best = i;
  }
  return best;
}

void note_held(std::vector<HeldEffect>& held, const std::string& effect, const std::string& reason) {
  for (const auto& h : held)
    if (h.effect == effect) return;
  held.push_back({effect, reason});
}

std::vector<TriedSubModel> tried_of(const Round& r) {
  std::vector<TriedSubModel> out;
  for (const auto& f : r.fits)
    if (f) out.push_back({f->model.text(), f->sse});
  return out;
}

}  // namespace

std::string NestingRefit::sentence() const {
  return from + " fitted better than " + model + ", which contains it (SSE " +
         format_number("%.4g", sse_from / sse_before) + " of " + model +
         "'s): the larger fit was off its optimum, so it was refitted from " + from +
         "'s fit with the extra effect neutral (now " + format_number("%.4g", sse_after / sse_before) +
         ") before any removal was judged.";
}

nlohmann::json to_json(const std::vector<TriedSubModel>& tried) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& t : tried) j.push_back({{"model", t.model}, {"sse", number_or_null(t.sse)}});
  return j;
}

std::vector<TriedSubModel> tried_sub_models_from_json(const nlohmann::json& j) {
  std::vector<TriedSubModel> out;
  for (const auto& t : j) out.push_back({t.at("model").get<std::string>(), number_or_inf(t.at("sse"))});
  return out;
}

nlohmann::json to_json(const std::vector<NestingRefit>& refits) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& n : refits)
    j.push_back({{"model", n.model},
                 {"from", n.from},
                 {"sse_before", number_or_null(n.sse_before)},
                 {"sse_from", number_or_null(n.sse_from)},
                 {"sse_after", number_or_null(n.sse_after)},
                 {"sentence", n.sentence()}});
  return j;
}

std::vector<NestingRefit> nesting_refits_from_json(const nlohmann::json& j) {
  std::vector<NestingRefit> out;
  for (const auto& n : j)
    out.push_back({n.at("model").get<std::string>(), n.at("from").get<std::string>(),
                   number_or_inf(n.at("sse_before")), number_or_inf(n.at("sse_from")),
                   number_or_inf(n.at("sse_after"))});
  return out;
}

Pruned prune(FitResult current, const std::string& keep, const ModelData& data, const FitOptions& fit,
             const KeepReason& keep_reason) {
  Pruned p{std::move(current), {}, {}, {}, {}};
  for (;;) {
    const Round r = try_removals(p.fit, keep, data, fit);
    if (auto n = lift(p.fit, r, data, fit)) p.refits.push_back(std::move(*n));
    p.tried = tried_of(r);
    std::vector<std::optional<std::string>> reasons(r.effects.size());
    if (keep_reason)
      for (std::size_t i = 0; i < r.effects.size(); ++i)
        if (r.fits[i]) reasons[i] = keep_reason(r.effects[i], p.fit, *r.fits[i]);
    const auto preferred = best_removal(p.fit, r, data, [](std::size_t) { return true; });
    if (preferred && reasons[*preferred]) note_held(p.held, r.effects[*preferred], *reasons[*preferred]);
    const auto removal = best_removal(p.fit, r, data, [&](std::size_t i) { return !reasons[i]; });
    if (!removal) {
      // A reason of an earlier round may have lapsed (its rival went) and
      // the effect gone since: only what stayed was kept.
      std::erase_if(p.held, [&](const HeldEffect& h) { return !p.fit.model.has(h.effect); });
      return p;
    }
    if (fit.status) fit.status("pruned " + r.effects[*removal]);
    p.removed.push_back(r.effects[*removal]);
    p.fit = *r.fits[*removal];
  }
}

}  // namespace hystbench
