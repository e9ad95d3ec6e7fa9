#pragma once
// Orthogonal forward regression (FROLS: Billings, Chen & Korenberg, Int. J.
// Control 49 (1989) 2157; Billings, Nonlinear System Identification, Wiley
// 2013, ch. 3): which few of many candidate columns explain a target.
//
// At each step every remaining column p_j is made orthogonal to the columns
// already chosen (q_j), and its error-reduction ratio
//
//   ERR_j = (q_jᵀe)² / (q_jᵀq_j · eᵀe)
//
// is the share of the target's sum of squares it explains beyond them.
// Without check rows the column with the largest ERR is chosen. With check
// rows (held-out samples), the choice is by held-out gain: among the columns
// whose ERR passes the BIC rule below, the one whose least-squares fit on
// the fit rows leaves the smallest residual on the check rows. The check
// rows of every column go through the same orthogonalisation, so that
// residual costs one pass over the check rows per column. Because each candidate is judged
// only on what the chosen ones leave, two correlated candidates cannot both
// be credited with the same variance, and a candidate that is nearly a
// combination of chosen ones (q_jᵀq_j below 1e−10 of p_jᵀp_j) is skipped.
//
// Columns that are in the model already (`fixed`: the directions its own
// parameters can move the output in) are taken before the first step:
// every candidate and the target lose their part along them, so a candidate
// is credited only with what a refit of the model's parameters could not
// do as well, and ERR is a share of what is left after that refit.
//
// Stopping rule: a step is taken only when
//   - it lowers the BIC by more than `bic_threshold` (default −10, the
//     significance rule of diagnose):
//       ΔBIC = N·ln(1 − ERR_j/(1 − ΣERR)) + ln N  ≤  bic_threshold,
//     N the number of rows of the fit;
//   - with check rows given (held-out samples the choice never sees), the
//     least-squares fit with the new column lowers their RMS residual by at
//     least `heldout_gain` (default 1 %), so that a column which only
//     follows the fit's own noise or colour is refused;
//   - and fewer than `max_terms` were taken.
//
// The chosen columns are fitted together with the fixed ones by least
// squares on the fit rows; standard errors assume white residuals (a
// coloured residual makes them optimistic).
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

struct ForwardRegressionOptions {
  int max_terms = 5;
  double bic_threshold = -10.0;
  double heldout_gain = 0.01;
};

// Candidate columns P, the target e and the fixed columns, on the same rows.
struct RegressionRows {
  Eigen::MatrixXd P;
  Eigen::VectorXd e;
  Eigen::MatrixXd fixed;  // any number of columns, possibly none
};

struct ForwardStep {
  int column = -1;
  double err = 0.0;        // share of eᵀe this column explains beyond the earlier ones
  double delta_bic = 0.0;  // of taking this step
  double check_rms = 0.0;  // RMS residual of the check rows after it (0 without check rows)
  int runner_up = -1;      // the best other column at this step, by the same rank (-1: none)
  double runner_up_err = 0.0;
};

struct ForwardRegression {
  std::vector<ForwardStep> steps;       // in the order chosen
  Eigen::VectorXd first_err;            // every column's ERR at the first step (0: skipped)
  Eigen::VectorXd coefficients;         // of the chosen columns, in step order
  Eigen::VectorXd standard_errors;
  // Of the fixed columns, in the same fit; 0 for a column that is a
  // combination of the others (left out of the fit).
  Eigen::VectorXd fixed_coefficients;
  double explained = 0.0;               // Σ ERR
  double fixed_share = 0.0;             // share of eᵀe the fixed columns took
  double check_rms = 0.0;               // of the check rows after the fixed columns alone
  // The first step refused and the rule that refused it ("bic", "heldout",
  // "max_terms"); column -1 when no candidate was left.
  ForwardStep refused;
  std::string refused_by;
};

// Deterministic: ties (ERRs equal to 1e−9, check residuals to 1e−6) go to
// the lower column index.
ForwardRegression forward_regression(const RegressionRows& fit, const ForwardRegressionOptions& options = {},
                                     const RegressionRows* check = nullptr);

}  // namespace hystbench
