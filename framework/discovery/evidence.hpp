#pragma once
// The plain sentence that explains one diagnosis candidate: what adding the
// effect did to the error, and what the effect's own residual statistic
// (EffectInfo::statistic) says of the current fit (docs/discovery.md).
#include <optional>
#include <string>

#include "framework/discovery/effect_signatures.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {

// `significant` says whether the candidate passed the diagnosis rule: the
// signature is then given as the reason it helps, otherwise as what would
// have pointed at it. `statistic`: the effect's signature on the current
// residual (signature_in over the signatures of the current fit's
// compare_signals); an effect without one is explained by its signature
// text and the error change.
std::string evidence_sentence(const EffectInfo& effect,
                              const std::optional<EffectSignature>& statistic,
                              const FitErrors& before, const FitErrors& after, double delta_bic,
                              bool significant, const std::string& y_unit);

}  // namespace hystbench
