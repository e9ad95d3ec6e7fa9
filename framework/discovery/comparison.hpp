#pragma once
// Comparing a model output with a measurement: the numbers behind
// `hystbench compare` (metrics.json). comparison_report.hpp writes them out.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hystbench {

struct ComparisonInput {
  Eigen::VectorXd t, u, y, y_model;  // physical units, same length
  std::vector<std::string> segment;  // one label per sample, or empty
  Eigen::VectorXd estimation;        // 1 = estimation sample, 0 = held out; empty = all estimation
  double sample_time = 0.0;          // 0: inferred from t
  std::string u_unit, y_unit;        // for tables and axes; may be empty
};

// Everything metrics.json holds. Metric groups have the keys of
// to_json(ErrorMetrics) (error_metrics.hpp): n, sse, rmse, fit_percent,
// relative_error, max_abs_error, mean_error. No value is NaN or infinite:
// an undefined number is null.
//
//  "n", "sample_time"
//  "all", "estimation", "heldout" (absent when nothing is held out)
//  "by_segment", "by_amplitude", "by_branch", "by_time"  (breakdowns.hpp)
//  "amplitude_binning": {"quantity": "|u - mean(u)|", "spacing": "equal width",
//                        "bins", "u_mean"}
//  "branch_tolerance":  |Δu| at or below which a sample is "holding" (units of u)
//  "residual": computed on the residual e = y − ŷ of the whole record
//     {"computed_on": "whole record", "mean", "std",
//      "acf":  {"lags": [1..25], "values", "bound", "outside"},
//      "ccf":  {"lags": [-25..25], "values", "bound", "outside", "peak_lag",
//               "input_lag1_autocorrelation": r_uu(1); near 1 the input is smooth
//               and r_ue spreads over many lags, so peak_lag is no delay estimate},
//      "ljung_box": {"lags": h = min(20, N/5), "q", "p_value"},
//      "white": p_value > 0.01,
//      "lowest_excitation_hz": lowest zero-crossing frequency of u over the segment
//                              runs (excitation_frequency.hpp)}
//     (stats/residual_correlation.hpp: conventions, τ > 0 = residual vs past input)
//  "noise_floor": {"sigma", "method", "rmse_over_sigma", "pairs", "period", "order"
//                  [, "heldout_rmse_over_sigma"]}   (noise_floor.hpp)
//  "signatures": every registered effect's own residual statistic, keyed by effect:
//                {"statistic", "value", "sentence", "details"} (effect_signatures.hpp)
//
// Throws std::invalid_argument when the lengths differ.
nlohmann::json compare_signals(const ComparisonInput& in);

// Only the metrics of the parts: {"all", "estimation", "heldout"} (the
// last absent when nothing is held out), as in compare_signals.
nlohmann::json part_metrics(const ComparisonInput& in);

constexpr int kCorrelationLags = 25;
constexpr int kLjungBoxLags = 20;
constexpr double kWhitenessLevel = 0.01;

}  // namespace hystbench
