#pragma once
// Backward elimination after an effect is added, under the nesting rule.
//
// Each effect but `keep` is removed in turn and the smaller model polished
// from the current fit; the removal that lowers the BIC most is made, and
// again, until no removal lowers it.
//
// Nesting rule: a model can always do what any of its sub-models does (the
// extra effects at their neutral values leave the signal unchanged), so a
// sub-model that fits better than the model containing it means the larger
// fit is off its optimum, not that the extra effect hurts. Before any
// removal is judged, the larger model is refitted from the best such
// sub-model's optimum with the removed effect at its neutral value and its
// parameters searched again (refit_warm, never worse than that start). Only
// then does BIC compare the two: a removal is then made on what the effect
// adds at its best, not on a poor local fit of it (docs/discovery.md,
// "Nested models").
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/discovery/model_fit.hpp"

namespace hystbench {

// A sub-model tried while pruning, with its estimation SSE (normalised).
struct TriedSubModel {
  std::string model;  // Model::text()
  double sse = 0.0;
};
nlohmann::json to_json(const std::vector<TriedSubModel>& tried);
std::vector<TriedSubModel> tried_sub_models_from_json(const nlohmann::json& j);

// One firing of the nesting rule: `model` was refitted from the optimum of
// its sub-model `from`.
struct NestingRefit {
  std::string model, from;
  double sse_before = 0.0, sse_from = 0.0, sse_after = 0.0;
  std::string sentence() const;
};
nlohmann::json to_json(const std::vector<NestingRefit>& refits);
std::vector<NestingRefit> nesting_refits_from_json(const nlohmann::json& j);

// The relative SSE margin by which a sub-model must beat its containing
// model for the rule to fire: far above rounding, far below any change
// BIC can see.
inline constexpr double kNestingTolerance = 1e-9;

// An effect whose removal BIC preferred, kept because the data gave no
// evidence of its absence.
struct HeldEffect {
  std::string effect, reason;
};

// Why `effect` must stay although BIC prefers `sub` (the fit without it)
// to `current`, or nothing when it may go.
using KeepReason = std::function<std::optional<std::string>(const std::string& effect, const FitResult& current,
                                                            const FitResult& sub)>;

struct Pruned {
  FitResult fit;
  std::vector<std::string> removed;
  std::vector<HeldEffect> held;
  // Sub-models of the final fit tried in the last round (each with one
  // effect less): the final fit's SSE is at most each of theirs.
  std::vector<TriedSubModel> tried;
  std::vector<NestingRefit> refits;
};

// `keep` is never tried out. An effect for which `keep_reason` gives a
// reason is tried (its sub-model counts for the nesting rule) but never
// removed; `held` records it when BIC preferred its removal.
Pruned prune(FitResult current, const std::string& keep, const ModelData& data, const FitOptions& fit,
             const KeepReason& keep_reason = {});

}  // namespace hystbench
