#pragma once
// What an effect's signature statistic sees of a fit (residual_signature.hpp):
// the record, the model output and the residual e = y − ŷ, in physical units,
// with the residual tests that several statistics share already computed.
// Nothing is copied; the view lives as long as the comparison that made it.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/stats/residual_correlation.hpp"

namespace hystbench {

struct ResidualView {
  const Eigen::VectorXd& t;                 // s, one per sample
  const Eigen::VectorXd& u;                 // input
  const Eigen::VectorXd& y_model;           // ŷ, the model output
  const Eigen::VectorXd& e;                 // y − ŷ
  const std::vector<std::string>& segment;  // one label per sample, or empty
  double sample_time;                       // s, > 0
  // r_ue(τ), τ = −25..25, with its 99 % band ±ccf.bound (residual_correlation.hpp:
  // τ > 0 pairs the residual with past input).
  const Correlation& ccf;
  // Lowest dominant frequency of u over the segment runs (from zero crossings);
  // 1 / record length when no run oscillates.
  double lowest_excitation_hz;
};

}  // namespace hystbench
