#pragma once
// Goodness-of-fit numbers of a model output ŷ against a measurement y, over
// all samples or over a chosen subset (a segment, an amplitude bin, ...).
//
// With e = y − ŷ over the n chosen samples:
//   sse            Σ e²
//   rmse           √(sse / n)                       (units of y)
//   fit_percent    100 (1 − ‖e‖ / ‖y − ȳ‖)          (NRMSE fit, system-identification convention)
//   relative_error ‖e‖ / ‖y‖                         (hysteresis-paper convention, no mean removal)
//   max_abs_error  max |e|                           (units of y)
//   mean_error     ē                                 (bias; units of y)
// A number that is undefined for the subset is NaN here and null in JSON:
// everything but n when n = 0; fit_percent when n < 2 or y is constant;
// relative_error when y is all zero.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <vector>

namespace hystbench {

struct ErrorMetrics {
  long n = 0;
  double sse, rmse, fit_percent, relative_error, max_abs_error, mean_error;
};

// Over the samples listed in `rows` (indices into y and y_model).
ErrorMetrics error_metrics(const Eigen::VectorXd& y, const Eigen::VectorXd& y_model,
                           const std::vector<Eigen::Index>& rows);
// Over every sample.
ErrorMetrics error_metrics(const Eigen::VectorXd& y, const Eigen::VectorXd& y_model);

// {"n", "sse", "rmse", "fit_percent", "relative_error", "max_abs_error", "mean_error"};
// NaN becomes null.
nlohmann::json to_json(const ErrorMetrics& m);

}  // namespace hystbench
