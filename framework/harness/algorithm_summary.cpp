#include "framework/harness/algorithm_summary.hpp"
#include "framework/io/json_number.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/stats/descriptive.hpp"

namespace hystbench {

AlgorithmSummary summarize(const std::string& label, const std::string& name,
                           const nlohmann::json& params,
                           const std::vector<std::string>& parameter_names,
                           std::vector<TrialResult> results) {
  // Trial order, not finishing order, so that the numbers never depend on
  // thread scheduling.
  std::sort(results.begin(), results.end(),
            [](const TrialResult& a, const TrialResult& b) { return a.trial < b.trial; });
  AlgorithmSummary s;
  s.label = label;
  s.name = name;
  s.params = params;
  s.parameter_names = parameter_names;
  s.trials = static_cast<long>(results.size());

  std::vector<double> finals, evaluations, iterations;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& r : results) {
    s.wall_seconds += r.wall_seconds;
    if (r.failed()) {
      if (s.failed++ == 0) s.first_failure = "trial " + std::to_string(r.trial) + ": " + r.message;
      continue;
    }
    finals.push_back(r.best);
    evaluations.push_back(double(r.evaluations));
    iterations.push_back(double(r.iterations));
    if (s.best_trial < 0 || r.best < best) {
      best = r.best;
      s.best_trial = r.trial;
      s.best_x = r.best_x;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.min = s.best = finals.empty() ? nan : *std::min_element(finals.begin(), finals.end());
  s.max = s.worst = finals.empty() ? nan : *std::max_element(finals.begin(), finals.end());
  s.mean = stats::mean(finals);
  s.median = stats::median(finals);
  s.std = finals.empty() ? nan : finals.size() < 2 ? 0.0 : stats::sample_std(finals);
  s.mean_evaluations = stats::mean(evaluations);
  s.mean_iterations = stats::mean(iterations);
  return s;
}

nlohmann::json AlgorithmSummary::to_json() const {
  nlohmann::json x = nlohmann::json::object();
  for (std::size_t i = 0; i < best_x.size() && i < parameter_names.size(); ++i)
    x[parameter_names[i]] = best_x[i];
  nlohmann::json j = {{"label", label},
                      {"name", name},
                      {"params", params},
                      {"trials", trials},
                      {"failed", failed},
                      {"best", number_or_null(best)},
                      {"mean", number_or_null(mean)},
                      {"worst", number_or_null(worst)},
                      {"median", number_or_null(median)},
                      {"std", number_or_null(std)},
                      {"min", number_or_null(min)},
                      {"max", number_or_null(max)},
                      {"evaluations", number_or_null(mean_evaluations)},
                      {"iterations", number_or_null(mean_iterations)},
                      {"wall_seconds", wall_seconds},
                      {"best_trial", best_trial},
                      {"best_x", x}};
  // Only when there is one, so that summaries of clean runs keep their shape.
  if (failed > 0) j["first_failure"] = first_failure;
  return j;
}

}  // namespace hystbench
