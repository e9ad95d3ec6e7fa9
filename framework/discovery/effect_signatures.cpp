#include "framework/discovery/effect_signatures.hpp"

#include <algorithm>

#include "framework/discovery/error_metrics.hpp"
#include "framework/io/json_number.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {

std::vector<EffectSignature> effect_signatures(const ResidualView& view) {
  std::vector<EffectSignature> out;
  for (const auto* info : EffectRegistry::instance().all()) {
    const ResidualSignature& s = info->statistic;
    if (!s.compute) continue;
    const SignatureValue v = s.compute(view);
    out.push_back({info->name, s.name, v, cite(s, v)});
  }
  return out;
}

nlohmann::json to_json(const std::vector<EffectSignature>& signatures) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& s : signatures) {
    nlohmann::json details = nlohmann::json::object();
    for (const auto& [name, x] : s.value.details) details[name] = number_or_null(x);
    out[s.effect] = {{"statistic", s.statistic},
                     {"value", number_or_null(s.value.value)},
                     {"sentence", s.sentence},
                     {"details", details}};
  }
  return out;
}

std::optional<EffectSignature> signature_in(const std::vector<EffectSignature>& signatures,
                                            const std::string& effect) {
  const auto it = std::find_if(signatures.begin(), signatures.end(),
                               [&](const EffectSignature& s) { return s.effect == effect; });
  return it == signatures.end() ? std::nullopt : std::optional<EffectSignature>(*it);
}

}  // namespace hystbench
