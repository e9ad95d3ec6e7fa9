#pragma once
// Two-sided Wilcoxon rank-sum (Mann-Whitney) test, exact for small samples
// (rank_sum_exact.hpp: both at most 10 values) and with the normal
// approximation above, and Holm's step-down correction for several tests.
//
// Wilcoxon, Biometrics Bulletin 1(6):80-83, 1945; Mann & Whitney, Ann. Math.
// Statist. 18(1):50-60, 1947; Holm, Scand. J. Statist. 6(2):65-70, 1979.
// The normal approximation is that of R's wilcox.test(exact = FALSE,
// correct = TRUE):
//   U_1   = W_1 - n_1 (n_1 + 1) / 2        (W_1: rank sum of the first sample,
//                                           ties averaged)
//   mu_U  = n_1 n_2 / 2
//   sig_U = sqrt(n_1 n_2 / 12 ((n + 1) - sum_t (t^3 - t) / (n (n - 1))))
//   z     = (U_1 - mu_U - 0.5 sign(U_1 - mu_U)) / sig_U
//   p     = 2 (1 - Phi(|z|))
// Lower values are better throughout (they are minimised objectives).
#include <vector>

namespace hystbench::stats {

struct RankSumResult {
  double u = 0.0;         // U_1 of the first sample
  double z = 0.0;         // continuity-corrected; 0 when every value ties
  double p = 1.0;         // two-sided
  bool exact = false;     // p from the permutation distribution, not from z
  bool all_tied = false;  // sig_U = 0: no evidence either way, p = 1
};

enum class RankSumMethod {
  Automatic,  // exact when rank_sum_exact_applies, else normal
  Normal,     // normal approximation whatever the sizes
};

// Throws InputError for an empty sample or a NaN value.
RankSumResult rank_sum_test(const std::vector<double>& first, const std::vector<double>& second,
                            RankSumMethod method = RankSumMethod::Automatic);

// Table mark of a reference algorithm (the proposed one) against a
// competitor; the character is what the table prints.
enum class Mark : char {
  Better = '+',  // reference significantly better
  Same = '=',    // no significant difference
  Worse = '-',   // reference significantly worse
};

// '=' unless p < alpha; then the lower median decides the direction, and
// when the medians are equal the lower mean rank (U_1 < mu_U) does.
Mark rank_sum_mark(const std::vector<double>& reference, const std::vector<double>& competitor,
                   double alpha = 0.05);

struct HolmResult {
  std::vector<double> adjusted;  // in input order; monotone in p, at most 1
  std::vector<bool> rejected;    // in input order
};

// Holm step-down over m p-values: with p_(1) <= ... <= p_(m), reject H_(i)
// while p_(i) < alpha / (m - i + 1), and retain it and all after it at the
// first failure. adjusted_(i) = min(1, max_{j <= i} (m - j + 1) p_(j)), so
// H_(i) is rejected exactly when adjusted_(i) < alpha. Throws InputError for
// a p-value outside [0, 1] (NaN included) or alpha outside (0, 1).
HolmResult holm(const std::vector<double>& p_values, double alpha = 0.05);

}  // namespace hystbench::stats
