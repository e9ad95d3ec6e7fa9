#include "framework/discovery/evidence.hpp"

#include "framework/core/text.hpp"

namespace hystbench {

std::string evidence_sentence(const EffectInfo& effect,
                              const std::optional<EffectSignature>& statistic,
                              const FitErrors& before, const FitErrors& after, double delta_bic,
                              bool significant, const std::string& y_unit) {
  const std::string unit = y_unit.empty() ? "" : " " + y_unit;
  std::string s = "Adding " + effect.name + " (" + effect.summary + ") changes the RMSE from " +
                  format_number("%.4g", before.rmse_estimation) + " to " +
                  format_number("%.4g", after.rmse_estimation) + unit;
  if (before.n_heldout)
    s += " (held out: " + format_number("%.4g", before.rmse_heldout) + " to " +
         format_number("%.4g", after.rmse_heldout) + unit + ")";
  s += ", ΔBIC = " + format_number("%.1f", delta_bic) + ". " +
       (significant ? "It helps because " : "Not significant; its signature would be that ") +
       effect.signature;
  if (statistic && !statistic->sentence.empty()) s += "; here " + statistic->sentence;
  return s + ".";
}

}  // namespace hystbench
