#pragma once
// Comparing a model output with a measurement: the numbers behind
// `hystbench compare` (metrics.json). comparison_report.hpp writes them out.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/discovery/breakdowns.hpp"
#include "framework/discovery/effect_signatures.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/excitation_content.hpp"
#include "framework/discovery/startup_transient.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/stats/residual_correlation.hpp"

namespace hystbench {

struct ComparisonInput {
  Eigen::VectorXd t, u, y, y_model;  // physical units, same length
  std::vector<std::string> segment;  // one label per sample, or empty
  Eigen::VectorXd estimation;        // 1 = estimation sample, 0 = held out; empty = all estimation
  double sample_time = 0.0;          // 0: inferred from t
  std::string u_unit, y_unit;        // for tables and axes; may be empty
  // Index in the record of the first sample compared (the warm-up's length):
  // advice that names a sample count (--warmup) counts from the record's start.
  Eigen::Index first_sample = 0;
  // What the samples not held out are to the model: it was fitted on them,
  // on another record (they are test samples), or the model file does not
  // say (an SVR model file does not name its training record).
  enum class Record { Fitted, Other, Unknown } record = Record::Fitted;
};

// What the report and figures call the samples not held out.
inline const char* estimation_name(const ComparisonInput& in) {
  switch (in.record) {
    case ComparisonInput::Record::Other: return "test";
    case ComparisonInput::Record::Unknown: return "not held out";
    default: return "estimation";
  }
}

// The error metrics of the parts of the record.
struct PartMetrics {
  ErrorMetrics all, estimation;
  std::optional<ErrorMetrics> heldout;  // empty when nothing is held out
};

// Tests of the residual e = y − ŷ of the whole record
// (stats/residual_correlation.hpp: conventions, τ > 0 = residual vs past input).
struct ResidualAnalysis {
  double mean = 0, std = 0;  // NaN when undefined (std needs two samples)
  Correlation acf;           // lags 1..kCorrelationLags
  Correlation ccf;           // input–residual, lags −kCorrelationLags..kCorrelationLags
  int peak_lag = 0;          // of ccf
  // r_uu(1): near 1 the input is smooth and r_ue spreads over many lags, so
  // peak_lag is no delay estimate.
  double input_lag1_autocorrelation = 0;
  LjungBox ljung_box;  // h = min(kLjungBoxLags, N/5)
  bool white = false;  // Ljung–Box p > kWhitenessLevel
  // Lowest zero-crossing frequency of u over the segment runs
  // (excitation_frequency.hpp).
  double lowest_excitation_hz = 0;
};

// The noise floor of the measurement, and the model's RMSE against it.
struct ComparedNoiseFloor : NoiseFloor {
  double rmse_over_sigma = 0;          // all samples; NaN when undefined
  double heldout_rmse_over_sigma = 0;  // NaN when undefined or nothing is held out
};

// Everything compare_signals computes. Metric groups are ErrorMetrics; a
// number that is undefined is NaN.
struct Comparison {
  Eigen::Index n = 0;
  double sample_time = 0;
  PartMetrics parts;
  std::vector<SegmentErrors> by_segment;  // breakdowns.hpp
  std::vector<AmplitudeErrors> by_amplitude;
  BranchErrors by_branch;
  std::vector<TimeErrors> by_time;
  double u_mean = 0;  // the amplitude bins are of |u − u_mean|
  // |Δu| at or below which a sample is "holding" (units of u).
  double branch_tolerance = 0;
  ResidualAnalysis residual;
  ComparedNoiseFloor noise_floor;  // noise_floor.hpp
  // Every registered effect's own residual statistic, in registry order
  // (effect_signatures.hpp).
  std::vector<EffectSignature> signatures;
  // What the record excites (excitation_content.hpp).
  ExcitationContent excitation;
  // Whether the first periods dominate the error (startup_transient.hpp).
  StartupTransient startup;
};

// Throws std::invalid_argument when the lengths differ.
Comparison compare_signals(const ComparisonInput& in);

// Only the metrics of the parts, as in compare_signals.
PartMetrics part_metrics(const ComparisonInput& in);

// {"all", "estimation", "heldout" (absent when nothing is held out)}, each
// with the keys of to_json(ErrorMetrics) (error_metrics.hpp).
nlohmann::json to_json(const PartMetrics& parts);

// metrics.json. No value is NaN or infinite: an undefined number is null.
//
//  "n", "sample_time"
//  "all", "estimation", "heldout" (absent when nothing is held out)
//  "by_segment", "by_amplitude", "by_branch", "by_time"  (breakdowns.hpp)
//  "amplitude_binning": {"quantity": "|u - mean(u)|", "spacing": "equal width",
//                        "bins", "u_mean"}
//  "branch_tolerance"
//  "residual": {"computed_on": "whole record", "mean", "std",
//      "acf":  {"lags": [1..25], "values", "bound", "outside"},
//      "ccf":  {"lags": [-25..25], "values", "bound", "outside", "peak_lag",
//               "input_lag1_autocorrelation"},
//      "ljung_box": {"lags", "q", "p_value"}, "white", "lowest_excitation_hz"}
//  "noise_floor": {"sigma", "method", "rmse_over_sigma", "pairs", "period", "order"
//                  [, "heldout_rmse_over_sigma"]}
//  "signatures": keyed by effect: {"statistic", "value", "sentence", "details"}
nlohmann::json to_json(const Comparison& c);

constexpr int kCorrelationLags = 25;
constexpr int kLjungBoxLags = 20;
constexpr double kWhitenessLevel = 0.01;

}  // namespace hystbench
