#pragma once
// The plain sentence that explains one diagnosis candidate: what adding the
// effect did to the error, and which residual statistic of the current fit
// points at it (DISCOVERY.md §2).
#include <nlohmann/json.hpp>
#include <string>

#include "framework/discovery/fit_errors.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {

// `significant` says whether the candidate passed the diagnosis rule: the
// signature is then given as the reason it helps, otherwise as what would
// have pointed at it. `signatures`: the "signatures" object of compare_signals for the current
// fit. Effects without a statistic of their own (user plugins) are
// explained by their signature sentence and the error change alone.
std::string evidence_sentence(const EffectInfo& effect, const nlohmann::json& signatures,
                              const FitErrors& before, const FitErrors& after, double delta_bic,
                              bool significant, const std::string& y_unit);

}  // namespace hystbench
