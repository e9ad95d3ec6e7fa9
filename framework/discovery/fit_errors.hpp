#pragma once
// The two numbers every discovery step is judged by: the RMSE on the samples
// the fit used and on the held-out samples, in the units of y.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>

#include "framework/model/model.hpp"

namespace hystbench {

struct FitErrors {
  bool stable = false;   // false: the model diverges on these data (errors are +inf)
  double sse = 0.0;      // normalised estimation SSE: the fitness
  long n_estimation = 0, n_heldout = 0;
  double rmse_estimation = 0.0, rmse_heldout = 0.0;  // physical; held-out 0 when none

  nlohmann::json to_json() const;
  // Inverse of to_json (the SSE is not stored there and reads back as 0).
  static FitErrors from_json(const nlohmann::json& j);
};

FitErrors fit_errors(const Model& model, const Eigen::VectorXd& x, const ModelData& data);

}  // namespace hystbench
