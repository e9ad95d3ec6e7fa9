#include "framework/discovery/fit_errors.hpp"

#include <cmath>
#include <limits>

#include "framework/io/json_number.hpp"

namespace hystbench {

FitErrors fit_errors(const Model& model, const Eigen::VectorXd& x, const ModelData& data) {
  FitErrors e;
  e.n_estimation = data.estimation_count();
  e.n_heldout = data.heldout_count();
  Eigen::VectorXd y;
  e.stable = model.simulate(x, data, y);
  if (!e.stable) {
    const double inf = std::numeric_limits<double>::infinity();
    e.sse = e.rmse_estimation = e.rmse_heldout = inf;
    return e;
  }
  const Eigen::ArrayXd sq = (data.y - y).array().square();
  e.sse = (sq * data.estimation.array()).sum();
  const double held = (sq * data.heldout_mask().array()).sum();
  e.rmse_estimation = std::sqrt(e.sse / double(e.n_estimation)) * data.scales.y;
  e.rmse_heldout = e.n_heldout ? std::sqrt(held / double(e.n_heldout)) * data.scales.y : 0.0;
  return e;
}

nlohmann::json FitErrors::to_json() const {
  return {{"stable", stable},
          {"estimation_samples", n_estimation},
          {"heldout_samples", n_heldout},
          {"rmse", number_or_null(rmse_estimation)},
          {"heldout_rmse", n_heldout ? number_or_null(rmse_heldout) : nlohmann::json()}};
}

FitErrors FitErrors::from_json(const nlohmann::json& j) {
  FitErrors e;
  e.stable = j.at("stable").get<bool>();
  e.n_estimation = j.at("estimation_samples").get<long>();
  e.n_heldout = j.at("heldout_samples").get<long>();
  // null is a diverged fit's infinite error; with nothing held out it is 0.
  e.rmse_estimation = number_or_inf(j.at("rmse"));
  e.rmse_heldout = e.n_heldout ? number_or_inf(j.at("heldout_rmse")) : 0.0;
  return e;
}

}  // namespace hystbench
