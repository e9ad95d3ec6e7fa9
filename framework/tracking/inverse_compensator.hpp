#pragma once
// Inverse compensation of an identified model's front (docs/tracking.md#inverse):
// at every sample, the input u in [u_min, u_max] whose front output w (the
// signal that enters the model's dynamics, in output units) equals a
// desired w*, found by a bracketed one-dimensional solve from the front's
// current state, then committed.
//
// Why a bracketed solve works: the front of a physical model (a gain, a
// Bouc–Wen loop of positive slope, a static polynomial of positive slope
// over the range) increases with the current input, so w(u) − w* changes
// sign once on the range. Where a model is not monotone (a fitted
// polynomial that folds over, a loop of negative slope), the solver still
// returns a root when the ends of the range differ in sign, but not
// necessarily the one continuity would pick; where they agree, no root is
// sought inside: the end nearer w* is taken and the sample counts as
// saturated, as it does when w* lies beyond what the range reaches.
#include <memory>

#include <string>

#include "framework/tracking/identified_model.hpp"

namespace hystbench {

struct InverseStatistics {
  long samples = 0;
  long saturated = 0;            // samples whose w* lay outside what [u_min, u_max] reaches
  double max_residual = 0.0;     // max |w(u) − w*| over the other samples, output units
  double sum_squared_residual = 0.0;
  int max_evaluations = 0;       // the most front evaluations one sample needed
  double rms_residual() const;
};

class InverseCompensator {
 public:
  // The front of a copy of `model` (at rest); `tolerance` on w in output
  // units. Throws InputError naming `description` when the front does not
  // move with the current input.
  InverseCompensator(const IdentifiedModel& model, const std::string& description, double u_min, double u_max,
                     double tolerance);
  InverseCompensator(const InverseCompensator& other);

  void reset();
  // The input that makes the front give `w_desired` now; the front moves on.
  double step(double w_desired);
  // The front's output for input u now, the state left as it was.
  double trial(double u);
  const InverseStatistics& statistics() const { return stats_; }

 private:
  std::unique_ptr<IdentifiedModel> model_;
  double u_min_, u_max_, tolerance_;
  InverseStatistics stats_;
};

}  // namespace hystbench
