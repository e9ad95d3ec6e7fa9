#pragma once
// A record of an input alone, for simulating a model on it: output zero,
// every sample in the estimation part.
#include "framework/model/model_data.hpp"

namespace hystbench {

inline ModelData input_record(const Eigen::VectorXd& u, double ts) {
  ModelData d;
  d.sample_time = ts;
  d.t = Eigen::VectorXd::LinSpaced(u.size(), 0.0, ts * double(u.size() - 1));
  d.u = u;
  d.y = Eigen::VectorXd::Zero(u.size());
  d.estimation = Eigen::VectorXd::Ones(u.size());
  return d;
}

}  // namespace hystbench
