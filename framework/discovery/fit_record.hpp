#pragma once
// fit.json: a fitted discovery model with everything needed to simulate it
// again on other data (effects, normalised parameters bit for bit, the
// signal scales they refer to, sub-steps) and to trust it (data, hold-out,
// metrics, options, seed, provenance).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/discovery/data_source.hpp"
#include "framework/model/model.hpp"

namespace hystbench {

struct FitRecord {
  Model model;
  Eigen::VectorXd x = {};  // normalised
  SignalScales scales = {};
  DataSource data = {};
  HoldoutSpec holdout = {};
  nlohmann::json details = nlohmann::json::object();  // metrics, options, seed, provenance

  // The "parameters" list: name, physical value and unit, normalised value.
  nlohmann::json parameters_json() const;
  nlohmann::json to_json() const;
  // Throws InputError naming the file and the bad key.
  static FitRecord read(const std::filesystem::path& path);
};

// A record of (model, x) fitted on `data`, with its errors, seed and
// provenance in `details`.
FitRecord make_fit_record(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                          const DataSource& source, const HoldoutSpec& holdout, std::uint64_t seed);

// Physical model output for `x` on `data`; false when the model is unstable
// there. With periods > 1 the record is taken as one period of a periodic
// input: it is simulated `periods` times in a row from rest and the last
// period is returned (periodic steady state, as benchmark test sets of one
// steady-state period require).
bool simulate_physical(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                       Eigen::VectorXd& y, int periods = 1);

}  // namespace hystbench
