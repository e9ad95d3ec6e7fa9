#pragma once
// A measurement prepared for model fitting: signals divided by fixed scales
// (so every effect's bounds are O(1)), time from 0, and which samples the
// fit may see.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/io/measurement.hpp"

namespace hystbench {

// Normalisation of u and y. A fit stores its scales, so that its parameters
// mean the same thing when the model is simulated on other data.
struct SignalScales {
  double u = 1.0;
  double y = 1.0;

  // RMS of u and of y (1 for an all-zero signal).
  static SignalScales of(const Measurement& m);
  static SignalScales from_json(const nlohmann::json& j, const std::string& where);
  nlohmann::json to_json() const;
};

struct ModelData {
  Eigen::VectorXd t;  // s, t[0] = 0
  Eigen::VectorXd u;  // u / scales.u
  Eigen::VectorXd y;  // y / scales.y
  double sample_time = 0.0;
  SignalScales scales;
  std::vector<std::string> segment;  // one label per sample, or empty
  // 1 for samples the fit uses (estimation), 0 for held-out and warm-up
  // samples.
  Eigen::VectorXd estimation;
  // The first `warmup` samples only bring the model's state to where the
  // record is (a start-up transient, an unknown initial state): they are
  // simulated but neither fitted nor held out, and no error counts them.
  Eigen::Index warmup = 0;
  // The record starts where a held input leaves the model (held_start.hpp),
  // at the level that matches the warm-up; false: at rest. Needs a warm-up.
  bool held_start = false;

  ModelData() = default;
  // Every sample is an estimation sample until a hold-out is applied.
  ModelData(const Measurement& m, SignalScales scales);

  Eigen::Index size() const { return t.size(); }
  // The first n samples (n <= size()), with their labels and mask.
  ModelData head(Eigen::Index n) const;
  Eigen::Index estimation_count() const;
  // 1 for held-out samples: neither estimation nor warm-up.
  Eigen::VectorXd heldout_mask() const;
  Eigen::Index heldout_count() const { return size() - warmup - estimation_count(); }
};

}  // namespace hystbench
