#include "framework/control/control_report.hpp"

#include "framework/io/json_number.hpp"
#include "framework/report/provenance.hpp"

namespace hystbench {
namespace {

nlohmann::json metrics_json(const MetricSummary& s) {
  nlohmann::json j = {{"never_converged_trials", s.never_converged}};
  for (const auto& [name, f] : kSuppressionMetrics)
    j[name] = {{"mean", number_or_null(s.mean.*f)}, {"std", number_or_null(s.sd.*f)}};
  return j;
}

nlohmann::json controller_json(const ControllerResult& r) {
  nlohmann::json j = {{"label", r.entry.label},
                      {"controller", r.entry.name},
                      {"params", r.entry.params.json()},
                      {"reconstructed", r.entry.reconstructed},
                      {"diverged", r.diverged_trials > 0},
                      {"diverged_trials", r.diverged_trials},
                      {"diverged_at_s", number_or_null(r.earliest_divergence_s)},
                      {"trials", r.trials.size()},
                      {"measured", metrics_json(r.measured)},
                      {"true", metrics_json(r.truth)}};
  if (r.entry.in_sweep) j["sweep_value"] = r.entry.sweep_value;
  if (r.estimate)
    j["secondary"] = {{"estimate", r.estimate->description},
                      {"phase_error_deg", r.estimate->error.phase_deg},
                      {"gain_ratio", r.estimate->error.gain_ratio}};
  return j;
}

}  // namespace

nlohmann::json control_json(const ControlExperiment& x, const ControlSetup& setup,
                            const ControlResults& results, int threads) {
  nlohmann::json controllers = nlohmann::json::array(), sweep = nlohmann::json::array();
  for (const auto& r : results.controllers)
    (r.entry.in_sweep ? sweep : controllers).push_back(controller_json(r));
  nlohmann::json j = {{"experiment", x.source},
                      {"trials", x.trials},
                      {"seed", x.seed},
                      {"setup", setup.to_json()},
                      {"uncontrolled", controller_json(results.uncontrolled)},
                      {"controllers", controllers},
                      {"provenance", provenance(threads, x.seed)}};
  if (!sweep.empty()) j["step_sweep"] = {{"param", x.sweep_param}, {"runs", sweep}};
  return j;
}

}  // namespace hystbench
