#include "framework/discovery/evidence.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

namespace hystbench {
namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

double stat(const nlohmann::json& s, const std::string& key) {
  const auto it = s.find(key);
  return it != s.end() && it->is_number() ? it->get<double>() : std::nan("");
}

// The statistic of the current residual that speaks for each catalog effect.
std::string statistic_text(const std::string& effect, const nlohmann::json& s) {
  auto corr = [&](const std::string& key, const std::string& what) {
    const double v = stat(s, key);
    return std::isnan(v) ? std::string() : "the residual correlates with " + what + " (r = " +
                                               fmt("%.2f", v) + ")";
  };
  const double ccf = stat(s, "dynamics_ccf_max_over_bound");
  const std::string dynamics =
      std::isnan(ccf) ? "" : "the input-residual cross-correlation reaches " + fmt("%.1f", ccf) +
                                 " times its 99 % band at positive lags";
  const std::map<std::string, std::function<std::string()>> texts{
      {"offset", [&] { return "the residual mean is " + fmt("%.2f", stat(s, "offset")) +
                              " residual standard deviations"; }},
      {"drift", [&] { return corr("drift", "time"); }},
      {"asymmetry", [&] { return corr("asymmetry", "u² − mean(u²)"); }},
      {"backlash", [&] { return corr("backlash", "the direction of motion sign(Δu)"); }},
      {"hysteresis", [&] { return corr("backlash", "the direction of motion sign(Δu)"); }},
      {"saturation", [&] { return "the top amplitude bin holds " +
                                  fmt("%.1f", stat(s, "saturation")) +
                                  " times its share of the squared error"; }},
      {"creep", [&] { return corr("creep", "the slowly filtered input"); }},
      {"delay", [&] { return "the cross-correlation peaks at lag " +
                             fmt("%.0f", stat(s, "delay_lag")) + " samples and " +
                             corr("delay_correlation", "−dŷ/dt"); }},
      {"msd", [&] { return dynamics; }},
      {"arx", [&] { return dynamics; }},
      {"second_mode", [&] { return dynamics; }},
      {"feedback_hysteresis", [&] { return dynamics; }},
  };
  const auto it = texts.find(effect);
  return it == texts.end() ? "" : it->second();
}

}  // namespace

std::string evidence_sentence(const EffectInfo& effect, const nlohmann::json& signatures,
                              const FitErrors& before, const FitErrors& after, double delta_bic,
                              bool significant, const std::string& y_unit) {
  const std::string unit = y_unit.empty() ? "" : " " + y_unit;
  std::string s = "Adding " + effect.name + " (" + effect.summary + ") changes the RMSE from " +
                  fmt("%.4g", before.rmse_estimation) + " to " +
                  fmt("%.4g", after.rmse_estimation) + unit;
  if (before.n_heldout)
    s += " (held out: " + fmt("%.4g", before.rmse_heldout) + " to " +
         fmt("%.4g", after.rmse_heldout) + unit + ")";
  s += ", ΔBIC = " + fmt("%.1f", delta_bic) + ". " +
       (significant ? "It helps because " : "Not significant; its signature would be that ") +
       effect.signature;
  const std::string statistic = statistic_text(effect.name, signatures);
  if (!statistic.empty()) s += "; here " + statistic;
  return s + ".";
}

}  // namespace hystbench
