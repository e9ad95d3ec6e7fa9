#pragma once
// Where the error sits: the error metrics (error_metrics.hpp) per group of
// samples. Every group has the keys of to_json(ErrorMetrics) plus its own.
//
//   by_part      "all", "estimation", "heldout" (absent when nothing is held out)
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
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

nlohmann::json by_segment(const BreakdownInput& in);
nlohmann::json by_amplitude(const BreakdownInput& in);
nlohmann::json by_branch(const BreakdownInput& in);
nlohmann::json by_time(const BreakdownInput& in);

}  // namespace hystbench
