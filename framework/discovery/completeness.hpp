#pragma once
// Is the model complete? Only when nothing systematic is left in its
// residual, on the data it was fitted to and on the held-out data:
//
//   complete  ⇔  RMSE ≤ tolerance·σ on the estimation AND on the held-out
//                samples (σ: the noise floor, noise_floor.hpp),
//                the residual is white (Ljung–Box p > 0.01), and at most
//                kChanceCcfLags of the input–residual cross-correlation lags
//                leave their 99 % band (2 of 51 by chance: binomial tail 1.4 %).
//
// An error below σ/tolerance on either part means the noise estimate is
// too high: a fit at or under the floor everywhere is then not judged
// (kind "noise_estimate_too_high"), and a systematic reason says so.
//
// The verdict of a diagnosis ("none": no catalog effect helps) is a
// different question: a model can be incomplete with no catalog effect that
// helps (the missing physics is not in the catalog, or the fit is stuck).
#include <nlohmann/json.hpp>
#include <string>

#include "framework/discovery/comparison.hpp"
#include "framework/discovery/fit_errors.hpp"

namespace hystbench {

constexpr double kFloorTolerance = 1.2;
constexpr int kChanceCcfLags = 2;

struct Completeness {
  bool complete = false;
  // "white_at_floor", "coloured_at_floor", "systematic", "no_noise_estimate"
  // or "noise_estimate_too_high" (an error below 1/tolerance σ);
  // a diagnosis turns "systematic" into "beyond_catalog" when no catalog
  // effect captures what is left (beyond_catalog.hpp).
  std::string kind = "systematic";
  std::string reason;  // one or two plain sentences with the numbers
  double sigma = 0.0;  // noise estimate, units of y
  double rmse_over_sigma = 0.0, heldout_rmse_over_sigma = 0.0;  // NaN when not defined
  bool white = false;  // Ljung–Box p > 0.01 and at most kChanceCcfLags lags outside
  double ljung_box_p = 0.0;
  int ccf_outside = 0, ccf_lags = 0;
  std::string worst_segment;  // the segment with the largest RMSE, "" without segments
  double worst_segment_rmse_over_sigma = 0.0;
  double tolerance = kFloorTolerance;

  nlohmann::json to_json() const;
};

// `where`: compare_signals of the fit; `errors`: its estimation and held-out
// errors (physical units).
Completeness assess_completeness(const FitErrors& errors, const Comparison& where,
                                 double tolerance = kFloorTolerance);

}  // namespace hystbench
