#pragma once
// The SVR Hammerstein-like model run one sample at a time in physical
// units, for a loop (docs/tracking.md#identified-models): stage 1 in free run
// (its own past outputs as regressors), then stage 2.
//
//   w(k+1) = stage 1 (x(k) .. x(k−m), w(k) .. w(k−n)),   y = stage 2 (w)
//
// The input x(k) sets the next front output w(k+1): front(u) returns that
// value, so front then back gives what the loop measures one sample after
// applying u, as for a catalog model driven one sample late.
#include <vector>

#include "framework/svr/svr_model.hpp"

namespace hystbench {

class SvrStream {
 public:
  // Starts at rest: every past input, front output and output 0 (the
  // actuator unpowered; stage 2's history then agrees with ArxFit::simulate).
  explicit SvrStream(const SvrHammerstein& model);

  void reset();
  // w(k+1) for input u(k); nothing moves.
  double predict_front(double u) const;
  // The same, and the histories move on.
  double step_front(double u);
  // Stage 2 at the front output w (w itself without a stage 2).
  double step_back(double w);

 private:
  void set_input(double u) const;

  const SvrHammerstein* model_;
  mutable Eigen::VectorXd row_;      // x(k) .. x(k−m), w(k) .. w(k−n) [, r(k)], scaled
  std::vector<double> back_in_, back_out_;  // w(k) .., y(k−1) .., newest first
};

}  // namespace hystbench
