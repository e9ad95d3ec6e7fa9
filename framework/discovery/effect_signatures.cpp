#include "framework/discovery/effect_signatures.hpp"

#include <cmath>
#include <limits>

#include "framework/discovery/error_metrics.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

double number_or_nan(const nlohmann::json& j) {
  return j.is_number() ? j.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

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
    for (const auto& [name, x] : s.value.details) details[name] = finite_or_null(x);
    out[s.effect] = {{"statistic", s.statistic},
                     {"value", finite_or_null(s.value.value)},
                     {"sentence", s.sentence},
                     {"details", details}};
  }
  return out;
}

std::optional<EffectSignature> signature_in(const nlohmann::json& comparison,
                                            const std::string& effect) {
  const auto all = comparison.find("signatures");
  if (all == comparison.end() || !all->is_object() || !all->contains(effect)) return std::nullopt;
  const nlohmann::json& j = (*all)[effect];
  EffectSignature s{effect,
                    j.value("statistic", ""),
                    {number_or_nan(j.value("value", nlohmann::json()))},
                    j.value("sentence", "")};
  const nlohmann::json details = j.value("details", nlohmann::json::object());
  for (auto it = details.begin(); it != details.end(); ++it)
    s.value.details.emplace_back(it.key(), number_or_nan(it.value()));
  return s;
}

}  // namespace hystbench
