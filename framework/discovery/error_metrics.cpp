#include "framework/discovery/error_metrics.hpp"

#include <cmath>
#include <limits>
#include <numeric>

#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

ErrorMetrics error_metrics(const Eigen::VectorXd& y, const Eigen::VectorXd& y_model,
                           const std::vector<Eigen::Index>& rows) {
  ErrorMetrics m{long(rows.size()), kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  if (rows.empty()) return m;
  double y_sum = 0, e_sum = 0, sse = 0, yy = 0, max_abs = 0;
  for (Eigen::Index i : rows) {
    const double e = y[i] - y_model[i];
    y_sum += y[i];
    e_sum += e;
    sse += e * e;
    yy += y[i] * y[i];
    max_abs = std::max(max_abs, std::abs(e));
  }
  const double n = double(rows.size());
  const double y_mean = y_sum / n;
  // Second pass for the spread of y: Σ(y − ȳ)² without cancellation.
  double y_spread = 0, y_scale = 0;
  for (Eigen::Index i : rows) {
    y_spread += (y[i] - y_mean) * (y[i] - y_mean);
    y_scale = std::max(y_scale, std::abs(y[i]));
  }
  m.sse = sse;
  m.rmse = std::sqrt(sse / n);
  m.max_abs_error = max_abs;
  m.mean_error = e_sum / n;
  // "Constant" allows for rounding: a spread at the level of the last bits
  // of y would turn the fit into noise.
  const double rounding = 1e-13 * y_scale * std::sqrt(n);
  if (rows.size() >= 2 && std::sqrt(y_spread) > rounding)
    m.fit_percent = 100.0 * (1.0 - std::sqrt(sse) / std::sqrt(y_spread));
  if (yy > 0) m.relative_error = std::sqrt(sse) / std::sqrt(yy);
  if (!std::isfinite(m.sse)) m = ErrorMetrics{m.n, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  return m;
}

ErrorMetrics error_metrics(const Eigen::VectorXd& y, const Eigen::VectorXd& y_model) {
  std::vector<Eigen::Index> rows(std::size_t(y.size()));
  std::iota(rows.begin(), rows.end(), Eigen::Index(0));
  return error_metrics(y, y_model, rows);
}

nlohmann::json to_json(const ErrorMetrics& m) {
  return {{"n", m.n},
          {"sse", number_or_null(m.sse)},
          {"rmse", number_or_null(m.rmse)},
          {"fit_percent", number_or_null(m.fit_percent)},
          {"relative_error", number_or_null(m.relative_error)},
          {"max_abs_error", number_or_null(m.max_abs_error)},
          {"mean_error", number_or_null(m.mean_error)}};
}

}  // namespace hystbench
