#pragma once
// A record and candidates for checking that an effect's batched form gives
// exactly its one-candidate values (tests/effect_lanes_test.cpp, and
// tests/lane_check.cpp for a generated effect built as a plugin).
#include "framework/core/eigen.hpp"
#include <cmath>
#include <numbers>

#include "framework/core/rng.hpp"
#include "framework/model/model.hpp"

namespace hystbench {

// A drive with steps, a sweep and a hold-out, normalised with unit scales;
// y is a model output plus noise so that SSEs are of realistic size.
inline ModelData lane_record(int n = 3000) {
  Eigen::VectorXd u(n);
  for (int k = 0; k < n; ++k) {
    const double t = 2e-3 * k;
    u[k] = (k / 500 % 2 ? 1.0 : -0.4) + 0.5 * std::sin(2 * std::numbers::pi * (1 + 3 * t) * t);
  }
  ModelData d;
  d.u = u;
  d.t = Eigen::VectorXd::LinSpaced(n, 0.0, 2e-3 * (n - 1));
  d.sample_time = 2e-3;
  Rng rng(5);
  d.y = u;
  for (int k = 0; k < n; ++k) d.y[k] = 0.8 * u[k] + 0.01 * rng.normal();
  d.estimation = Eigen::VectorXd::Ones(n);
  d.estimation.tail(n / 4).setZero();
  return d;
}

// Candidates across the box; some at the neutral value (pass-through), at
// the box edges, and outside the valid region (unstable ARX poles).
inline Eigen::MatrixXd lane_candidates(const Model& model, Eigen::Index n, std::uint64_t seed) {
  const Bounds b = model.bounds();
  Rng rng(seed);
  Eigen::MatrixXd X(model.dimension(), n);
  for (Eigen::Index j = 0; j < n; ++j) {
    for (int i = 0; i < model.dimension(); ++i) X(i, j) = rng.uniform(b.lower[i], b.upper[i]);
    if (j % 5 == 1) X.col(j) = model.neutral();
    if (j % 7 == 2) X(1, j) = model.neutral()[1];  // first effect's first parameter only
    if (j % 6 == 3) X.col(j) = b.upper;
  }
  return X;
}

}  // namespace hystbench
