#pragma once
// Friedman test with average ranks over N blocks (problems) and k
// algorithms, the Iman-Davenport F statistic, the Nemenyi critical
// difference and the comparison of every algorithm with a control under
// Holm's correction (Demsar, JMLR 7:1-30, 2006, section 3.2.2):
//   R_j    = (1/N) sum_i r_ij               r_ij: rank in block i, 1 = lowest
//   chi2_F = 12 N / (k (k + 1)) (sum_j R_j^2 - k (k + 1)^2 / 4)   ~ chi2(k - 1)
//   F_F    = (N - 1) chi2_F / (N (k - 1) - chi2_F)        ~ F(k - 1, (k - 1)(N - 1))
//   CD     = q_alpha sqrt(k (k + 1) / (6 N))
//   z_j    = (R_j - R_control) / sqrt(k (k + 1) / (6 N)),  p_j two-sided normal
// Lower values are better: each block is ranked by the given value, ties
// averaged, so +inf (a failed algorithm) ranks last.
#include <vector>

namespace hystbench::stats {

struct FriedmanResult {
  int blocks = 0;                   // N
  int algorithms = 0;               // k
  std::vector<double> average_ranks;  // R_j, algorithm order of the input
  double chi2 = 0.0;                // chi2_F
  double chi2_p = 1.0;              // P(chi2(k - 1) > chi2_F)
  // Iman-Davenport F_F. +inf when every block ranks the algorithms in the
  // same order without ties (chi2_F reaches its maximum N (k - 1)); then
  // f_p = 0.
  double f = 0.0;
  double f_p = 1.0;                 // P(F(k - 1, (k - 1)(N - 1)) > F_F)
};

// values[i][j]: value of algorithm j on block i. Throws InputError for
// fewer than 2 blocks (F_F would have 0 denominator degrees of freedom),
// fewer than 2 algorithms, rows of unequal length or a NaN value.
FriedmanResult friedman_test(const std::vector<std::vector<double>>& values);

// q_0.05 of the Nemenyi test (Studentized range / sqrt 2) for k = 2..10, as
// tabulated by Demsar (2006, table 5a); InputError for other k.
double nemenyi_q05(int algorithms);
// CD at alpha = 0.05: two average ranks further apart than this differ.
double nemenyi_critical_difference(int algorithms, int blocks);

struct ControlComparison {
  int algorithm = 0;      // index j in the Friedman input
  double z = 0.0;         // > 0: j ranks worse than the control
  double p = 1.0;         // two-sided, unadjusted
  double p_holm = 1.0;    // Holm-adjusted over the k - 1 comparisons
  bool rejected = false;  // Holm step-down at alpha
};

// One entry per algorithm other than `control`, in input order. InputError
// for a control index out of range.
std::vector<ControlComparison> compare_with_control(const FriedmanResult& result, int control,
                                                    double alpha = 0.05);

}  // namespace hystbench::stats
