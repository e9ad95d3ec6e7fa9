#include "framework/discovery/completeness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/text.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void worst_segment(const Comparison& where, Completeness& c) {
  double worst = -1;
  for (const auto& s : where.by_segment)
    if (s.metrics.rmse > worst) worst = s.metrics.rmse, c.worst_segment = s.segment;
  c.worst_segment_rmse_over_sigma = worst >= 0 && c.sigma > 0 ? worst / c.sigma : kNaN;
}

std::string statistics_text(const Completeness& c, bool heldout) {
  std::string s = "RMSE " + format_number("%.3g", c.rmse_over_sigma) + " σ on the estimation data";
  if (heldout) s += " and " + format_number("%.3g", c.heldout_rmse_over_sigma) + " σ held out";
  s += " (σ = " + format_number("%.4g", c.sigma) + "), Ljung–Box p = " + format_number("%.3g", c.ljung_box_p) + ", " +
       std::to_string(c.ccf_outside) + " of " + std::to_string(c.ccf_lags) +
       " input–residual cross-correlation lags outside the 99 % band";
  if (!c.worst_segment.empty())
    s += "; the error is largest in segment " + c.worst_segment + " (" +
         format_number("%.3g", c.worst_segment_rmse_over_sigma) + " σ)";
  return s;
}

}  // namespace

Completeness assess_completeness(const FitErrors& errors, const Comparison& where,
                                 double tolerance) {
  Completeness c;
  c.sigma = where.noise_floor.sigma;
  c.ljung_box_p = where.residual.ljung_box.p_value;
  c.ccf_outside = where.residual.ccf.outside;
  c.ccf_lags = int(where.residual.ccf.lags.size());
  const bool heldout = errors.n_heldout > 0;
  c.rmse_over_sigma = c.sigma > 0 ? errors.rmse_estimation / c.sigma : kNaN;
  c.heldout_rmse_over_sigma = heldout && c.sigma > 0 ? errors.rmse_heldout / c.sigma : kNaN;
  worst_segment(where, c);
  c.tolerance = tolerance;
  c.white = c.ljung_box_p > kWhitenessLevel && c.ccf_outside <= kChanceCcfLags;
  if (!(c.sigma > 0)) {
    c.kind = "no_noise_estimate";
    c.reason = "No noise estimate: completeness cannot be judged against the noise floor.";
    return c;
  }
  // No model fits below the noise: an error well under the estimate says the
  // estimate is too high (records of several realisations with transients
  // between them inflate the high-order differences it is taken from). A
  // part above the floor stays systematic, since a smaller σ only makes it
  // more so; only a fit at or under the floor everywhere is left unjudged.
  const double lowest = heldout ? std::min(c.rmse_over_sigma, c.heldout_rmse_over_sigma) : c.rmse_over_sigma;
  const bool above = c.rmse_over_sigma > tolerance || (heldout && c.heldout_rmse_over_sigma > tolerance);
  const std::string too_high = lowest < 1.0 / tolerance
                                   ? " The noise estimate is too high on this record (an error of " +
                                         format_number("%.3g", lowest) + " σ is below any the noise allows), so "
                                         "these ratios understate what is left."
                                   : "";
  if (lowest < 1.0 / tolerance && !above) {
    c.kind = "noise_estimate_too_high";
    c.reason = "The noise estimate is wrong on this record: the " +
               std::string(heldout && c.heldout_rmse_over_sigma < c.rmse_over_sigma ? "held-out" : "estimation") +
               " error is " + format_number("%.3g", lowest) +
               " σ, below any error the noise would allow, so completeness is not judged against it (" +
               statistics_text(c, heldout) + ").";
    return c;
  }
  const bool at_floor = c.rmse_over_sigma <= tolerance &&
                        (!heldout || c.heldout_rmse_over_sigma <= tolerance);

  const std::string numbers = statistics_text(c, heldout) + ".";
  c.complete = at_floor && c.white;
  if (c.complete) {
    c.kind = "white_at_floor";
    c.reason = "The residual is white and the error is at the noise estimate on the estimation" +
               std::string(heldout ? " and the held-out data" : " data") + ": " + numbers;
  } else if (at_floor) {
    c.kind = "coloured_at_floor";
    c.reason = "The error is at the noise estimate, but the residual is not white (coloured "
               "noise, or a small systematic error): " + numbers;
  } else {
    c.kind = "systematic";
    c.reason = "Something systematic is left: " + numbers + too_high;
  }
  return c;
}

nlohmann::json Completeness::to_json() const {
  return {{"complete", complete},
          {"kind", kind},
          {"reason", reason},
          {"sigma", number_or_null(sigma)},
          {"rmse_over_sigma", number_or_null(rmse_over_sigma)},
          {"heldout_rmse_over_sigma", number_or_null(heldout_rmse_over_sigma)},
          {"ljung_box_p", number_or_null(ljung_box_p)},
          {"ccf_outside", ccf_outside},
          {"ccf_lags", ccf_lags},
          {"worst_segment", worst_segment},
          {"worst_segment_rmse_over_sigma", number_or_null(worst_segment_rmse_over_sigma)},
          {"white", white},
          {"tolerance", tolerance}};
}

}  // namespace hystbench
