#include "framework/discovery/comparison.hpp"

#include <cmath>
#include <stdexcept>

#include "framework/discovery/excitation_frequency.hpp"
#include "framework/io/json_number.hpp"

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

double branch_tolerance(const Eigen::VectorXd& u) {
  double max_step = 0;
  for (Eigen::Index k = 1; k < u.size(); ++k)
    max_step = std::max(max_step, std::abs(u[k] - u[k - 1]));
  return kHoldingTolerance * max_step;
}

ResidualAnalysis analyse_residual(const ComparisonInput& in, const Eigen::VectorXd& e, double ts) {
  ResidualAnalysis r;
  const auto n = e.size();
  r.mean = n ? e.mean() : NAN;
  r.std = n >= 2 ? std::sqrt((e.array() - r.mean).square().sum() / double(n - 1)) : NAN;
  r.acf = autocorrelation(e, kCorrelationLags);
  r.ccf = cross_correlation(in.u, e, kCorrelationLags);
  r.peak_lag = peak_lag(r.ccf);
  r.input_lag1_autocorrelation = autocorrelation(in.u, 1).values[0];
  r.ljung_box = ljung_box(e, kLjungBoxLags);
  r.white = std::isfinite(r.ljung_box.p_value) && r.ljung_box.p_value > kWhitenessLevel;
  r.lowest_excitation_hz = lowest_excitation_frequency(in.u, in.segment, ts);
  return r;
}

ComparedNoiseFloor compare_to_noise_floor(const NoiseFloor& f, const PartMetrics& parts) {
  const auto ratio = [&](const ErrorMetrics& m) {
    return std::isfinite(m.rmse) && f.sigma > 0 ? m.rmse / f.sigma : NAN;
  };
  return {f, ratio(parts.all), parts.heldout ? ratio(*parts.heldout) : NAN};
}

// ---- JSON ------------------------------------------------------------------

template <class T>
nlohmann::json list_json(const std::vector<T>& items) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& x : items) out.push_back(to_json(x));
  return out;
}

nlohmann::json numbers(const std::vector<double>& v) {
  nlohmann::json out = nlohmann::json::array();
  for (double x : v) out.push_back(number_or_null(x));
  return out;
}

nlohmann::json to_json(const Correlation& c) {
  return {{"lags", c.lags},
          {"values", numbers(c.values)},
          {"bound", number_or_null(c.bound)},
          {"outside", c.outside}};
}

nlohmann::json to_json(const ResidualAnalysis& r) {
  nlohmann::json ccf = to_json(r.ccf);
  ccf["peak_lag"] = r.peak_lag;
  ccf["input_lag1_autocorrelation"] = number_or_null(r.input_lag1_autocorrelation);
  const LjungBox& lb = r.ljung_box;
  return {{"computed_on", "whole record"},
          {"mean", number_or_null(r.mean)},
          {"std", number_or_null(r.std)},
          {"acf", to_json(r.acf)},
          {"ccf", ccf},
          {"ljung_box",
           {{"lags", lb.lags},
            {"q", number_or_null(lb.q)},
            {"p_value", number_or_null(lb.p_value)}}},
          {"white", r.white},
          {"lowest_excitation_hz", number_or_null(r.lowest_excitation_hz)}};
}

nlohmann::json to_json(const ComparedNoiseFloor& f, bool heldout, double sample_time) {
  nlohmann::json out = {{"sigma", number_or_null(f.sigma)},
                        {"method", f.method},
                        {"rmse_over_sigma", number_or_null(f.rmse_over_sigma)},
                        {"pairs", f.pairs},
                        {"period", f.period},
                        {"order", f.order}};
  if (f.method == "spectral") out["quiet_from_hz"] = f.quiet_from / sample_time;
  if (heldout) out["heldout_rmse_over_sigma"] = number_or_null(f.heldout_rmse_over_sigma);
  return out;
}

}  // namespace

PartMetrics part_metrics(const ComparisonInput& in) {
  check_lengths(in);
  const auto mask = estimation_mask(in);
  std::vector<Eigen::Index> estimation, heldout;
  for (std::size_t i = 0; i < mask.size(); ++i)
    (mask[i] ? estimation : heldout).push_back(Eigen::Index(i));
  PartMetrics out{error_metrics(in.y, in.y_model), error_metrics(in.y, in.y_model, estimation), {}};
  if (!heldout.empty()) out.heldout = error_metrics(in.y, in.y_model, heldout);
  return out;
}

Comparison compare_signals(const ComparisonInput& in) {
  Comparison c;
  c.parts = part_metrics(in);  // checks the lengths
  c.n = in.t.size();
  c.sample_time = sample_time(in);
  const auto mask = estimation_mask(in);
  const BreakdownInput parts{in.t, in.u, in.y, in.y_model, in.segment, mask};
  c.by_segment = by_segment(parts);
  c.by_amplitude = by_amplitude(parts);
  c.u_mean = in.u.size() ? in.u.mean() : NAN;
  c.by_branch = by_branch(parts);
  c.branch_tolerance = branch_tolerance(in.u);
  c.by_time = by_time(parts);

  const Eigen::VectorXd e = in.y - in.y_model;
  c.residual = analyse_residual(in, e, c.sample_time);
  c.noise_floor = compare_to_noise_floor(estimate_noise_floor(in.u, in.y, in.segment), c.parts);
  const ResidualAnalysis& r = c.residual;
  c.signatures = effect_signatures(
      {in.t, in.u, in.y_model, e, in.segment, c.sample_time, r.ccf, r.lowest_excitation_hz});
  c.excitation = describe_excitation(in.u, in.segment, c.sample_time, in.u_unit);
  c.startup = find_startup_transient(e, c.excitation, in.first_sample);
  return c;
}

nlohmann::json to_json(const PartMetrics& parts) {
  nlohmann::json out;
  out["all"] = to_json(parts.all);
  out["estimation"] = to_json(parts.estimation);
  if (parts.heldout) out["heldout"] = to_json(*parts.heldout);
  return out;
}

nlohmann::json to_json(const Comparison& c) {
  nlohmann::json out = to_json(c.parts);
  out["n"] = c.n;
  out["sample_time"] = number_or_null(c.sample_time);
  out["by_segment"] = list_json(c.by_segment);
  out["by_amplitude"] = list_json(c.by_amplitude);
  out["amplitude_binning"] = {{"quantity", "|u - mean(u)|"},
                              {"spacing", "equal width"},
                              {"bins", kAmplitudeBins},
                              {"u_mean", number_or_null(c.u_mean)}};
  out["by_branch"] = to_json(c.by_branch);
  out["branch_tolerance"] = number_or_null(c.branch_tolerance);
  out["by_time"] = list_json(c.by_time);
  out["residual"] = to_json(c.residual);
  out["noise_floor"] = to_json(c.noise_floor, c.parts.heldout.has_value(), c.sample_time);
  out["signatures"] = to_json(c.signatures);
  out["excitation"] = c.excitation.to_json();
  out["startup_transient"] = c.startup.to_json();
  return out;
}

}  // namespace hystbench
