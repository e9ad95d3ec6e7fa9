#include "framework/discovery/comparison.hpp"

#include <cmath>
#include <stdexcept>

#include "framework/discovery/breakdowns.hpp"
#include "framework/discovery/effect_signatures.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/excitation_frequency.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/stats/residual_correlation.hpp"

namespace hystbench {
namespace {

void check_lengths(const ComparisonInput& in) {
  const auto n = in.t.size();
  if (in.u.size() != n || in.y.size() != n || in.y_model.size() != n ||
      (!in.segment.empty() && Eigen::Index(in.segment.size()) != n) ||
      (in.estimation.size() != 0 && in.estimation.size() != n))
    throw std::invalid_argument(
        "compare_signals: t, u, y, y_model, and segment and estimation when given, must have the "
        "same length (t has " +
        std::to_string(n) + " samples)");
}

double sample_time(const ComparisonInput& in) {
  if (in.sample_time > 0) return in.sample_time;
  const auto n = in.t.size();
  const double inferred = n >= 2 ? (in.t[n - 1] - in.t[0]) / double(n - 1) : 0.0;
  return inferred > 0 && std::isfinite(inferred) ? inferred : 1.0;
}

std::vector<bool> estimation_mask(const ComparisonInput& in) {
  std::vector<bool> mask(std::size_t(in.t.size()), true);
  for (Eigen::Index i = 0; i < in.estimation.size(); ++i)
    mask[std::size_t(i)] = in.estimation[i] != 0;
  return mask;
}

nlohmann::json numbers(const std::vector<double>& v) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(finite_or_null(x));
  return out;
}

nlohmann::json correlation_json(const Correlation& c) {
  return {{"lags", c.lags},
          {"values", numbers(c.values)},
          {"bound", finite_or_null(c.bound)},
          {"outside", c.outside}};
}

nlohmann::json residual_json(const Eigen::VectorXd& u, const Eigen::VectorXd& e,
                             const Correlation& acf, const Correlation& ccf) {
  const LjungBox lb = ljung_box(e, kLjungBoxLags);
  const auto n = e.size();
  const double mean = n ? e.mean() : NAN;
  const double std = n >= 2 ? std::sqrt((e.array() - mean).square().sum() / double(n - 1)) : NAN;
  nlohmann::json ccf_json = correlation_json(ccf);
  ccf_json["peak_lag"] = peak_lag(ccf);
  // A smooth (narrow-band) input spreads r_ue over many lags; readers need
  // to know before taking the peak lag for a delay.
  ccf_json["input_lag1_autocorrelation"] = finite_or_null(autocorrelation(u, 1).values[0]);
  return {
      {"computed_on", "whole record"},
      {"mean", finite_or_null(mean)},
      {"std", finite_or_null(std)},
      {"acf", correlation_json(acf)},
      {"ccf", ccf_json},
      {"ljung_box",
       {{"lags", lb.lags}, {"q", finite_or_null(lb.q)}, {"p_value", finite_or_null(lb.p_value)}}},
      {"white", std::isfinite(lb.p_value) && lb.p_value > kWhitenessLevel}};
}

nlohmann::json noise_json(const NoiseFloor& f, const nlohmann::json& all,
                          const nlohmann::json& heldout) {
  const auto ratio = [&](const nlohmann::json& m) {
    return m["rmse"].is_number() && f.sigma > 0 ? finite_or_null(m["rmse"].get<double>() / f.sigma)
                                                : nlohmann::json();
  };
  nlohmann::json out = {{"sigma", finite_or_null(f.sigma)},
                        {"method", f.method},
                        {"rmse_over_sigma", ratio(all)},
                        {"pairs", f.pairs},
                        {"period", f.period},
                        {"order", f.order}};
  if (!heldout.is_null()) out["heldout_rmse_over_sigma"] = ratio(heldout);
  return out;
}

}  // namespace

nlohmann::json part_metrics(const ComparisonInput& in) {
  check_lengths(in);
  const auto mask = estimation_mask(in);
  std::vector<Eigen::Index> estimation, heldout;
  for (std::size_t i = 0; i < mask.size(); ++i)
    (mask[i] ? estimation : heldout).push_back(Eigen::Index(i));
  nlohmann::json out;
  out["all"] = to_json(error_metrics(in.y, in.y_model));
  out["estimation"] = to_json(error_metrics(in.y, in.y_model, estimation));
  if (!heldout.empty()) out["heldout"] = to_json(error_metrics(in.y, in.y_model, heldout));
  return out;
}

nlohmann::json compare_signals(const ComparisonInput& in) {
  check_lengths(in);
  const double ts = sample_time(in);
  const auto mask = estimation_mask(in);
  const BreakdownInput parts{in.t, in.u, in.y, in.y_model, in.segment, mask};

  nlohmann::json out = part_metrics(in);
  out["n"] = in.t.size();
  out["sample_time"] = finite_or_null(ts);

  out["by_segment"] = by_segment(parts);
  out["by_amplitude"] = by_amplitude(parts);
  out["amplitude_binning"] = {{"quantity", "|u - mean(u)|"},
                              {"spacing", "equal width"},
                              {"bins", kAmplitudeBins},
                              {"u_mean", finite_or_null(in.u.size() ? in.u.mean() : NAN)}};
  out["by_branch"] = by_branch(parts);
  double max_step = 0;
  for (Eigen::Index k = 1; k < in.u.size(); ++k)
    max_step = std::max(max_step, std::abs(in.u[k] - in.u[k - 1]));
  out["branch_tolerance"] = finite_or_null(kHoldingTolerance * max_step);
  out["by_time"] = by_time(parts);

  const Eigen::VectorXd e = in.y - in.y_model;
  const Correlation acf = autocorrelation(e, kCorrelationLags);
  const Correlation ccf = cross_correlation(in.u, e, kCorrelationLags);
  const double f_low = lowest_excitation_frequency(in.u, in.segment, ts);
  out["residual"] = residual_json(in.u, e, acf, ccf);
  out["residual"]["lowest_excitation_hz"] = finite_or_null(f_low);
  out["noise_floor"] = noise_json(estimate_noise_floor(in.u, in.y, in.segment), out["all"],
                                  out.contains("heldout") ? out["heldout"] : nlohmann::json());
  out["signatures"] =
      to_json(effect_signatures({in.t, in.u, in.y_model, e, in.segment, ts, ccf, f_low}));
  return out;
}

}  // namespace hystbench
