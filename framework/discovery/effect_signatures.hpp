#pragma once
// The signature statistic of every registered effect on one residual: the
// framework names no effect, it asks each one (its EffectInfo::statistic,
// residual_signature.hpp), built-in or loaded with --plugin, for its number
// and the sentence that cites it. `compare` writes them to metrics.json and
// report.md; `diagnose` quotes a candidate's own as its evidence.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/model/residual_signature.hpp"

namespace hystbench {

struct EffectSignature {
  std::string effect;     // registered name
  std::string statistic;  // the statistic's name
  SignatureValue value;
  std::string sentence;  // the effect's sentence with the numbers; empty when undefined
};

// One per registered effect that declares a statistic, in registry order.
std::vector<EffectSignature> effect_signatures(const ResidualView& view);

// {"<effect>": {"statistic", "value" (null when undefined), "sentence",
//               "details": {"<name>": number or null, ...}}, ...}
nlohmann::json to_json(const std::vector<EffectSignature>& signatures);

// The signature of `effect` among `signatures` (those of a compare_signals
// result, comparison.hpp); nullopt when it has none.
std::optional<EffectSignature> signature_in(const std::vector<EffectSignature>& signatures,
                                            const std::string& effect);

}  // namespace hystbench
