#pragma once
// Before an effect is added, the current fit must be at its optimum: an
// effect "found" by a fit that is stuck in a poor basin only stands in for
// the better basin (a backlash of width 1e-10 credited with the gain of a
// refit). The symptom is a held-out error far above the estimation error,
// or a held-out error above the noise floor while the estimation error is
// at it. Then, before any candidate is tried:
//   - global restarts of the current model compete with the current fit;
//   - the effect(s) owning the most correlated pair of parameters (a delay
//     trading against an ARX block's own lag) are searched again from their
//     neutral values with the rest held, then everything is polished.
// The best estimation SSE wins; held-out data never choose.
#include <string>
#include <vector>

#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/model_fit.hpp"

namespace hystbench {

// Held-out RMSE above this multiple of the estimation RMSE is suspect.
constexpr double kHeldoutGapRatio = 1.5;

struct OptimumCheck {
  bool triggered = false;
  std::string reason;                // why it was triggered (or why not)
  std::vector<std::string> actions;  // what was tried, each with its result
  bool improved = false;
  FitErrors before, after;

  nlohmann::json to_json() const;
  static OptimumCheck from_json(const nlohmann::json& j);  // inverse of to_json
};

// Whether (errors, sigma) look like a fit off its optimum; sets `reason`.
bool suspect_optimum(const FitErrors& errors, double sigma, std::string& reason);

// The check and, when triggered, the restarts. `fit` is replaced by the
// better fit when one is found.
OptimumCheck ensure_optimum(FitResult& fit, const ModelData& data, double sigma,
                            const FitOptions& options);

}  // namespace hystbench
