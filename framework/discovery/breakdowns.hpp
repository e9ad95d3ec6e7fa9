#pragma once
// Where the error sits: the error metrics (error_metrics.hpp) per group of
// samples. In JSON every group has the keys of to_json(ErrorMetrics) plus its own.
//
//   by_segment   [{"segment", "part": "estimation"|"heldout"|"mixed", metrics}],
//                labels in order of first appearance; empty without labels
//   by_amplitude [{"bin", "u_low", "u_high", metrics}]: kAmplitudeBins equal-width
//                bins of the amplitude a = |u − mean(u)|; u_low..u_high is the
//                range of a (units of u), so the last bin holds the largest drive
//                in either direction
//   by_branch    {"loading": Δu > tol, "unloading": Δu < −tol, "holding": |Δu| ≤ tol},
//                Δu_k = u_k − u_{k−1} (the first sample takes the branch of the
//                second), tol = 10⁻³ · max |Δu|
//   by_time      [{"window", "t_start", "t_end", metrics}]: kTimeWindows windows of
//                equal sample count (fewer when there are fewer samples)
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/error_metrics.hpp"
#include "framework/model/regressors.hpp"  // branches, amplitude_bins

namespace hystbench {

constexpr int kTimeWindows = 10;

struct BreakdownInput {
  const Eigen::VectorXd& t;
  const Eigen::VectorXd& u;
  const Eigen::VectorXd& y;
  const Eigen::VectorXd& y_model;
  const std::vector<std::string>& segment;  // empty or one per sample
  const std::vector<bool>& estimation;      // one per sample
};

struct SegmentErrors {
  std::string segment;
  std::string part;  // "estimation", "heldout" or "mixed"
  ErrorMetrics metrics;
};

struct AmplitudeErrors {
  int bin = 0;
  double u_low = 0, u_high = 0;  // range of |u − mean(u)|, units of u
  ErrorMetrics metrics;
};

struct BranchErrors {
  ErrorMetrics loading, unloading, holding;
};

struct TimeErrors {
  Eigen::Index window = 0;
  double t_start = 0, t_end = 0;  // times of its first and last sample
  ErrorMetrics metrics;
};

std::vector<SegmentErrors> by_segment(const BreakdownInput& in);
std::vector<AmplitudeErrors> by_amplitude(const BreakdownInput& in);
BranchErrors by_branch(const BreakdownInput& in);
std::vector<TimeErrors> by_time(const BreakdownInput& in);

// One group each, as listed above; NaN becomes null.
nlohmann::json to_json(const SegmentErrors& g);
nlohmann::json to_json(const AmplitudeErrors& g);
nlohmann::json to_json(const BranchErrors& b);
nlohmann::json to_json(const TimeErrors& g);

}  // namespace hystbench
