#pragma once
// Signature statistics of a residual e = y − ŷ: one number per missing
// physical effect (DISCOVERY.md §2), each computed on the whole record.
// Correlations are Pearson coefficients in [−1, 1]; null when a signal is
// constant or the statistic does not apply.
//
//  offset                      mean(e) / std(e): a constant sensor offset
//  drift                       corr(e, t): linear sensor drift
//  asymmetry                   corr(e, u² − mean(u²)) (Billings–Voon u²′): even
//                              nonlinearity, loops not symmetric
//  backlash                    corr(e, sign(Δu)): error switches with the direction
//                              of motion (play, dead band)
//  saturation                  saturation_sse_share / saturation_sample_share: > 1
//                              when the error crowds into the top amplitude bin
//  saturation_sse_share        share of the SSE in the top |u − mean u| bin
//  saturation_sample_share     share of the samples in that bin
//  creep                       corr(e, u_slow), u_slow = u through a first-order lag
//                              with a time constant of one period of the lowest
//                              excitation frequency f_low: slow drift towards the
//                              input level
//  creep_low_frequency_share   var(moving mean of e over one period of f_low) / var(e):
//                              share of residual power below f_low
//  lowest_excitation_hz        f_low, from zero crossings of u − mean per segment run
//                              (1 / record length when no run oscillates)
//  dynamics_rate_correlation   corr(|e|, |Δu|): error grows with the input rate
//  dynamics_frequency_correlation
//                              corr(segment RMSE, log10 segment frequency) over
//                              segments (null for fewer than 3 distinct frequencies)
//  dynamics_rmse_per_hz        least-squares slope of segment RMSE vs segment
//                              frequency (units of y per Hz; null as above)
//  dynamics_ccf_max_over_bound max over τ = 1..25 of |r_ue(τ)| / (99 % band): above 1
//                              means input–residual correlation at positive lags
//  delay_lag                   lag (samples) of the largest |r_ue(τ)|, τ = −25..25
//  delay_ccf                   r_ue at that lag
//  delay_correlation           corr(e, −dŷ/dt): a delay d gives e ≈ −d·dŷ/dt
//  delay_seconds               least-squares d in e ≈ −d·dŷ/dt (central differences)
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/residual_correlation.hpp"

namespace hystbench {

struct SignatureInput {
  const Eigen::VectorXd& t;
  const Eigen::VectorXd& u;
  const Eigen::VectorXd& y_model;
  const Eigen::VectorXd& e;                 // y − ŷ
  const std::vector<std::string>& segment;  // empty or one per sample
  double sample_time;                       // > 0
  const Correlation& ccf;                   // cross_correlation(u, e, 25)
};

nlohmann::json residual_signatures(const SignatureInput& in);

// Pearson correlation; NaN when either signal is constant or n < 2.
double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

// Dominant frequency of u over [begin, end) from the zero crossings of
// u − mean (Hz); NaN when it crosses fewer than twice.
double crossing_frequency(const Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index end,
                          double sample_time);

}  // namespace hystbench
